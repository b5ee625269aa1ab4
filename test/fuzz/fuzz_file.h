/*
 * pcl_tensor fuzzing: the loaders read paths, so each input is written to a per-process file first.
 */
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace pcl_tensor_fuzz
{
  /** Write \a size bytes to a file named \a name in the temp folder (unique per process). */
  inline std::string
  writeInput (const std::string& name, const std::uint8_t* data, std::size_t size)
  {
    const char* tmp = std::getenv ("TMPDIR");
    const std::string path = std::string (tmp ? tmp : "/tmp") + "/pcl_tensor_" + std::to_string (::getpid ()) + "_" + name;
    std::ofstream (path, std::ios::binary | std::ios::trunc).write (reinterpret_cast<const char*> (data), static_cast<std::streamsize> (size));
    return path;
  }
}
