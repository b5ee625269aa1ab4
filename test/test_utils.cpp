#include "test_utils.h"

#include <fstream>

namespace pcl_tensor_test
{
  std::string
  sharedDataPath (const std::string& relative)
  {
    const std::string path = std::string (PCL_TENSOR_SHARED_DATA) + "/" + relative;
    return std::ifstream (path).good () ? path : std::string ();
  }
}
