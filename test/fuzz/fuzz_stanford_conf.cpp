/*
 * libFuzzer target: the Stanford .conf parser. Any bytes either parse or throw pcl::IOException;
 * what parses is written back and must read back to the same numbers.
 */
#include "fuzz_file.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/stanford_conf.h>

#include <cstdlib>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  const std::string path = pcl_tensor_fuzz::writeInput ("fuzz.conf", data, size);
  std::vector<pcl::io::StanfordConfEntry> entries;
  try
  {
    entries = pcl::io::loadStanfordConf (path);
  }
  catch (const pcl::IOException&)
  {
    return 0;
  }
  for (const auto& e : entries)
    if (!e.translation.allFinite () || !e.quaternion.coeffs ().allFinite () || !(e.quaternion.norm () > 0.0))
      std::abort ();  // the parser promised a valid pose
  try
  {
    pcl::io::saveStanfordConf (path, entries);
  }
  catch (const pcl::IOException&)
  {
    return 0;  // a file name that a .conf cannot hold (white space)
  }
  const auto again = pcl::io::loadStanfordConf (path);
  if (again.size () != entries.size ())
    std::abort ();
  for (std::size_t i = 0; i < entries.size (); ++i)
    if (again[i].file != entries[i].file || again[i].translation != entries[i].translation ||
        again[i].quaternion.coeffs () != entries[i].quaternion.coeffs ())
      std::abort ();
  return 0;
}
