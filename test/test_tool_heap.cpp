/*
 * pcl_tensor: the register tool's heap (apps/tool_main.h): once keepFreedMemoryForReuse() has run,
 * blocks of megabytes come from a heap region advised for transparent huge pages.
 */
#include "../apps/tool_main.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define PCL_TENSOR_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PCL_TENSOR_ASAN 1
#endif
#endif

namespace
{
  /** The VmFlags line of the mapping in /proc/self/smaps that holds \a address ("" when none). */
  std::string
  vmFlagsAt (std::uintptr_t address)
  {
    std::ifstream smaps ("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline (smaps, line))
    {
      std::istringstream head (line);
      std::uintptr_t low = 0, high = 0;
      char dash = 0;
      if (head >> std::hex >> low >> dash >> high && dash == '-')
        inside = low <= address && address < high;
      else if (inside && line.rfind ("VmFlags:", 0) == 0)
        return line;
    }
    return "";
  }
}

// After the call, an 8 MB block (far above glibc's usual mmap threshold) is carved from the heap grown
// for it, whose mapping carries the huge-page advice ("hg").
TEST (ToolHeap, RegisterToolsHeapIsAdvisedForHugePages)
{
#ifdef PCL_TENSOR_ASAN
  GTEST_SKIP () << "AddressSanitizer's allocator replaces glibc's heap";
#endif
  if (!std::ifstream ("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP () << "this kernel has no transparent huge pages";
  pcl_tensor_tools::keepFreedMemoryForReuse ();
  std::vector<char> block (8 << 20);
  const std::string flags = vmFlagsAt (reinterpret_cast<std::uintptr_t> (block.data ()) + (4 << 20));
  EXPECT_NE (flags.find (" hg"), std::string::npos) << "the block's mapping: " << flags;
}
