/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/atomic_file.h>
#include <pcl/common/tensor_exceptions.h>

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace pcl
{
  namespace io
  {
    namespace
    {
      namespace fs = std::filesystem;

      /** `.STEM.tmp-PID-N.EXT` beside \a destination: the pid tells processes apart, the counter the
        * writers of one process (threads included). */
      std::string
      temporaryPathFor (const fs::path& destination)
      {
        static std::atomic<unsigned long long> counter{0};
        const std::string name = "." + destination.stem ().string () + ".tmp-" + std::to_string (::getpid ()) + "-" +
                                 std::to_string (counter.fetch_add (1)) + destination.extension ().string ();
        return (destination.parent_path () / name).string ();
      }
    }

    AtomicFileWriter::AtomicFileWriter (const std::string& path) : path_ (path)
    {
      const fs::path destination = fs::absolute (path);
      std::error_code ec;
      if (!fs::is_directory (destination.parent_path (), ec))
        PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path << "': no folder " << destination.parent_path ());
      if (fs::is_directory (destination, ec))
        PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path << "': it is a folder");
      temporary_path_ = temporaryPathFor (destination);
    }

    AtomicFileWriter::~AtomicFileWriter ()
    {
      if (!committed_)
      {
        std::error_code ignored;  // a destructor must not throw; a leftover temporary is only clutter
        fs::remove (temporary_path_, ignored);
      }
    }

    void
    AtomicFileWriter::commit ()
    {
      if (committed_)
        PCL_TENSOR_THROW (pcl::IOException, "'" << path_ << "' is already committed");
      std::error_code ec;
      if (!fs::is_regular_file (temporary_path_, ec))
        PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path_ << "': nothing was written to " << temporary_path_);
      fs::rename (temporary_path_, path_, ec);
      if (ec)
        PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path_ << "': " << ec.message ());
      committed_ = true;
    }

    void
    writeFileAtomically (const std::string& path, std::string_view bytes)
    {
      AtomicFileWriter writer (path);
      std::FILE* file = std::fopen (writer.temporaryPath ().c_str (), "wb");
      if (!file)
        PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path << "': " << std::strerror (errno));
      // A full disk can show only when the buffer is flushed, at fclose: both results count.
      const bool written = std::fwrite (bytes.data (), 1, bytes.size (), file) == bytes.size ();
      const bool closed = std::fclose (file) == 0;
      if (!written || !closed)
        PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path << "': " << std::strerror (errno));
      writer.commit ();
    }
  }
}
