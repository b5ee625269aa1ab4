/*
 * pcl_tensor: what every file reader of pcl_tensor_io does before and while it reads (internal).
 */
#pragma once

#include <pcl/common/tensor_exceptions.h>
#include <pcl/console/print.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      /** \brief Throw pcl::IOException unless \a path is a file this process can open for reading.
        * A directory opens like a file on Linux but reads as nothing, so it is refused by name.
        */
      inline void
      requireReadableFile (const std::string& path)
      {
        std::error_code ec;
        if (std::filesystem::is_directory (path, ec))
          PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' is a directory, not a file");
        if (!std::ifstream (path).good ())
          PCL_TENSOR_THROW (pcl::IOException, "cannot open '" << path << "'");
      }

      /** \brief Throw pcl::IOException naming the file and line a header reader stopped at. */
      [[noreturn]] inline void
      throwAtLine (const std::string& path, int line_no, const std::string& what)
      {
        PCL_TENSOR_THROW (pcl::IOException, path << ":" << line_no << ": " << what);
      }

      /** \brief While alive, PCL's console prints nothing: PCL's readers report a bad file in
        * several lines of their own before returning an error, which our one exception replaces.
        */
      class QuietPclConsole
      {
        public:
          QuietPclConsole () : saved_ (pcl::console::getVerbosityLevel ()) { pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS); }
          ~QuietPclConsole () { pcl::console::setVerbosityLevel (saved_); }
          QuietPclConsole (const QuietPclConsole&) = delete;
          QuietPclConsole& operator= (const QuietPclConsole&) = delete;

        private:
          pcl::console::VERBOSITY_LEVEL saved_;
      };
    }
  }
}
