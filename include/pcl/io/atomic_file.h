/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <string>
#include <string_view>

namespace pcl
{
  namespace io
  {
    /** \brief Replace a file all at once: write to a temporary file in the destination's folder, then
      * commit() renames it over the destination. A reader, or a second process writing the same file,
      * sees the old content or the new, never part of one; of two writers the last to commit wins.
      *
      * Any writer that takes a path works through it, e.g. a PLY:
      * \code
      * pcl::io::AtomicFileWriter out ("model.ply");
      * if (pcl::io::savePLYFileBinary (out.temporaryPath (), mesh) < 0) throw ...;
      * out.commit ();
      * \endcode
      * A writer destroyed before commit() (an exception, a failed save) removes its temporary file
      * and leaves the destination as it was.
      *
      * The temporary is named `.STEM.tmp-PID-N.EXT` beside the destination (PID: this process, N: a
      * counter of this process), so that writers never share one, and writers that pick the format by
      * the extension (pcl::io::save) still see the destination's.
      * \note Nothing is synced to disk: a power loss may leave the destination empty or torn, which
      * the cache's checksum (TensorViewCache) then reports as CORRUPT or TRUNCATED.
      * \ingroup io
      */
    class AtomicFileWriter
    {
      public:
        /** \brief Prepare to replace \a path; nothing is written yet.
          * \throw pcl::IOException when the destination's folder does not exist or \a path names a folder */
        explicit AtomicFileWriter (const std::string& path);

        /** \brief Remove the temporary file unless commit() succeeded. */
        ~AtomicFileWriter ();

        AtomicFileWriter (const AtomicFileWriter&) = delete;
        AtomicFileWriter& operator= (const AtomicFileWriter&) = delete;

        /** \brief The destination. */
        const std::string& path () const { return path_; }

        /** \brief Where to write the content: a file in the destination's folder that no other writer uses. */
        const std::string& temporaryPath () const { return temporary_path_; }

        /** \brief Rename the temporary file over the destination, atomically.
          * \throw pcl::IOException when nothing was written to temporaryPath(), when called twice, or when
          * the rename fails (the temporary is then removed by the destructor) */
        void commit ();

        /** \brief True once commit() has succeeded. */
        bool committed () const { return committed_; }

      private:
        std::string path_;
        std::string temporary_path_;
        bool committed_{false};
    };

    /** \brief Write \a bytes to \a path through an AtomicFileWriter: all of them or, on failure, none.
      * \throw pcl::IOException when the folder is missing or a write, flush or the rename fails
      * \ingroup io
      */
    void
    writeFileAtomically (const std::string& path, std::string_view bytes);
  }
}
