/*
 * pcl_tensor evaluation: the shared main() of the eval_* programs.
 */
#include "eval_main.h"

#include <pcl/console/parse.h>

#include <cstdio>
#include <exception>
#include <iostream>

namespace pcl_tensor_eval
{
  int
  evalMain (int argc, char** argv, const char* name, const std::function<void (const char*)>& help,
            const std::function<int (int, char**)>& run)
  {
    if (argc < 2 || pcl::console::find_switch (argc, argv, "-h") || pcl::console::find_switch (argc, argv, "--help"))
    {
      help (argv[0]);
      return argc < 2 ? 2 : 0;
    }
    // Line-buffered even into a file: long runs are followed with tail -f.
    std::setvbuf (stdout, nullptr, _IOLBF, 0);
    try
    {
      return run (argc, argv);
    }
    catch (const std::exception& e)
    {
      std::cerr << name << ": error: " << e.what () << std::endl;
      return 1;
    }
  }
}
