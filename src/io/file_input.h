/*
 * pcl_tensor: what every file reader of pcl_tensor_io does before and while it reads (internal).
 */
#pragma once

#include <pcl/common/tensor_exceptions.h>
#include <pcl/console/print.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <istream>
#include <streambuf>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      /** \brief Throw pcl::IOException when \a path is a directory: it opens like a file on Linux but
        * reads as nothing, so it is refused by name.
        */
      inline void
      refuseDirectory (const std::string& path)
      {
        std::error_code ec;
        if (std::filesystem::is_directory (path, ec))
          PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' is a directory, not a file");
      }

      /** \brief Throw pcl::IOException unless \a path is a file this process can open for reading
        * (for files that another library reads; our readers use readFile()).
        */
      inline void
      requireReadableFile (const std::string& path)
      {
        refuseDirectory (path);
        if (!std::ifstream (path).good ())
          PCL_TENSOR_THROW (pcl::IOException, "cannot open '" << path << "'");
      }

      /** \brief Read \a path in blocks, handing each to \a sink (bytes, size); pcl::IOException when it
        * cannot be opened or a read fails midway. A stream read that fails looks like the end of the
        * file, so the readers would report a device error (EIO) as a cut or malformed file: stdio's
        * error flag tells them apart.
        */
      template <typename Sink> void
      readFileBlocks (const std::string& path, Sink sink)
      {
        refuseDirectory (path);
        const std::unique_ptr<std::FILE, int (*) (std::FILE*)> file (std::fopen (path.c_str (), "rb"), &std::fclose);
        if (!file)
          PCL_TENSOR_THROW (pcl::IOException, "cannot open '" << path << "': " << std::strerror (errno));
        char buffer[1 << 16];
        std::size_t n;
        while ((n = std::fread (buffer, 1, sizeof (buffer), file.get ())) > 0)
          sink (buffer, n);
        if (std::ferror (file.get ()))
          PCL_TENSOR_THROW (pcl::IOException, "cannot read '" << path << "': " << std::strerror (errno));
      }

      /** \brief The whole content of \a path (readFileBlocks()). */
      inline std::string
      readFile (const std::string& path)
      {
        std::string data;
        readFileBlocks (path, [&data] (const char* bytes, std::size_t n) { data.append (bytes, n); });
        return data;
      }

      /** \brief An istream over bytes already in memory, without the copy std::istringstream makes,
        * for the header parsers; rest() is what they have not read (the body).
        */
      class ByteStream : private std::streambuf, public std::istream
      {
        public:
          explicit ByteStream (std::string_view bytes) : std::istream (this)
          {
            char* begin = const_cast<char*> (bytes.data ());  // only read: a get area is never written
            setg (begin, begin, begin + bytes.size ());
          }
          std::string_view rest () const { return {gptr (), static_cast<std::size_t> (egptr () - gptr ())}; }
      };

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
