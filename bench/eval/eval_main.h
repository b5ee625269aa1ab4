/*
 * pcl_tensor evaluation: the shared main() of the eval_* programs.
 */
#pragma once

#include <functional>

namespace pcl_tensor_eval
{
  /** \brief Print help on -h/--help (exit 0) or without arguments (exit 2); otherwise run with stdout
    * line-buffered, and turn an exception into one "NAME: error: ..." line on stderr and exit code 1.
    */
  int
  evalMain (int argc, char** argv, const char* name, const std::function<void (const char*)>& help,
            const std::function<int (int, char**)>& run);
}
