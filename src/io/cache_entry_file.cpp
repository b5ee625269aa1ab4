/*
 * pcl_tensor: the frame of a cache entry file: header, payload, checksum (internal; TensorViewCache).
 */
#include "cache_entry_file.h"
#include "byte_codec.h"
#include "file_input.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include <sys/types.h>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      namespace
      {
        // PNG's trick: a high byte, CR LF and ^Z show a file mangled by a text-mode transfer.
        constexpr char kMagic[8] = {'\x89', 'T', 'V', 'C', 'A', '\r', '\n', '\x1a'};
        constexpr std::size_t kVersionEnd = 12;
        constexpr std::size_t kHeaderSize = 40;
        constexpr std::size_t kChecksumSize = 8;

        struct EntryHeader
        {
          std::uint32_t kind = 0;
          TensorViewCacheKey key;
          std::uint64_t payload_size = 0;
        };

        using File = std::unique_ptr<std::FILE, int (*) (std::FILE*)>;

        /** The state the header alone gives, with \a file_size the real size of the file. */
        CacheEntryState
        checkHeader (std::string_view header, std::uint64_t file_size, EntryHeader& out)
        {
          const std::string_view magic (kMagic, sizeof (kMagic));
          if (header.size () < magic.size ())
            return magic.substr (0, header.size ()) == header ? CacheEntryState::TRUNCATED : CacheEntryState::CORRUPT;
          if (header.substr (0, magic.size ()) != magic)
            return CacheEntryState::CORRUPT;
          if (header.size () < kVersionEnd)
            return CacheEntryState::TRUNCATED;
          ByteReader in (header.substr (magic.size ()));
          if (in.get<std::uint32_t> () != TENSOR_VIEW_CACHE_VERSION)
            return CacheEntryState::OTHER_VERSION;
          if (header.size () < kHeaderSize)
            return CacheEntryState::TRUNCATED;
          out.kind = in.get<std::uint32_t> ();
          out.key.source = in.get<std::uint64_t> ();
          out.key.preparation = in.get<std::uint64_t> ();
          out.payload_size = in.get<std::uint64_t> ();
          // Compared without forming header + payload + checksum, which a garbage size would overflow.
          const std::uint64_t room = file_size < kHeaderSize + kChecksumSize ? 0 : file_size - kHeaderSize - kChecksumSize;
          if (file_size < kHeaderSize + kChecksumSize || out.payload_size > room)
            return CacheEntryState::TRUNCATED;
          return out.payload_size < room ? CacheEntryState::CORRUPT : CacheEntryState::VALID;
        }

        /** Read \a size bytes in blocks, handing each to \a sink.
          * \return false when the file ends first */
        template <typename Sink> bool
        readBlocks (std::FILE* file, const std::string& path, std::uint64_t size, Sink sink)
        {
          char buffer[1 << 16];
          while (size > 0)
          {
            const std::size_t want = static_cast<std::size_t> (std::min<std::uint64_t> (size, sizeof (buffer)));
            const std::size_t got = std::fread (buffer, 1, want, file);
            if (std::ferror (file))
              PCL_TENSOR_THROW (pcl::IOException, "cannot read '" << path << "': " << std::strerror (errno));
            sink (buffer, got);
            if (got < want)
              return false;
            size -= got;
          }
          return true;
        }

        /** \a path opened for reading, and in \a size the size of the file opened: a writer may
          * rename another file over the path meanwhile. */
        File
        openEntry (const std::string& path, std::uint64_t& size)
        {
          File file (std::fopen (path.c_str (), "rb"), &std::fclose);
          if (!file || ::fseeko (file.get (), 0, SEEK_END) != 0)
            PCL_TENSOR_THROW (pcl::IOException, "cannot open '" << path << "': " << std::strerror (errno));
          const off_t end = ::ftello (file.get ());
          if (end < 0 || ::fseeko (file.get (), 0, SEEK_SET) != 0)
            PCL_TENSOR_THROW (pcl::IOException, "cannot read '" << path << "': " << std::strerror (errno));
          size = static_cast<std::uint64_t> (end);
          return file;
        }

        /** After a whole header: the payload (its first \a keep bytes kept) and the checksum. */
        CacheEntryState
        readPayload (std::FILE* file, const std::string& path, const EntryHeader& h, std::size_t keep, ContentHash& hash,
                     std::string& payload)
        {
          const bool whole_payload = readBlocks (file, path, h.payload_size, [&] (const char* bytes, std::size_t n) {
            hash.update (bytes, n);
            payload.append (bytes, std::min (n, keep - std::min (keep, payload.size ())));
          });
          std::string checksum;
          const bool whole_checksum = readBlocks (file, path, kChecksumSize, [&] (const char* bytes, std::size_t n) {
            checksum.append (bytes, n);
          });
          if (!whole_payload || !whole_checksum)
            return CacheEntryState::TRUNCATED;  // cut after it was opened
          if (ByteReader (checksum).get<std::uint64_t> () != hash.digest ())
            return CacheEntryState::CORRUPT;
          return CacheEntryState::VALID;
        }
      }

      std::string
      encodeCacheEntry (CacheEntryKind kind, const TensorViewCacheKey& key, std::string_view payload)
      {
        ByteWriter out;
        out.bytes ().append (kMagic, sizeof (kMagic));
        out.put (TENSOR_VIEW_CACHE_VERSION).put (static_cast<std::uint32_t> (kind));
        out.put (key.source).put (key.preparation).put (static_cast<std::uint64_t> (payload.size ()));
        out.bytes ().append (payload);
        out.put (hashBytes (out.bytes ()));
        return std::move (out.bytes ());
      }

      CacheEntryRead
      readCacheEntry (const std::string& path, CacheEntryKind kind, const TensorViewCacheKey& key, std::size_t keep)
      {
        CacheEntryRead r;
        std::error_code ec;
        const auto status = std::filesystem::status (path, ec);
        if (!std::filesystem::exists (status))
          return r;
        r.state = CacheEntryState::CORRUPT;
        if (!std::filesystem::is_regular_file (status))
          return r;
        std::uint64_t size = 0;
        const File file = openEntry (path, size);
        std::string header;
        readBlocks (file.get (), path, std::min<std::uint64_t> (size, kHeaderSize), [&] (const char* bytes, std::size_t n) {
          header.append (bytes, n);
        });
        EntryHeader h;
        r.state = checkHeader (header, size, h);
        if (r.state != CacheEntryState::VALID)
          return r;
        ContentHash hash;
        hash.update (header);
        r.state = readPayload (file.get (), path, h, keep, hash, r.payload);
        if (r.state == CacheEntryState::VALID && h.kind != static_cast<std::uint32_t> (kind))
          r.state = CacheEntryState::CORRUPT;
        else if (r.state == CacheEntryState::VALID && h.key != key)
          r.state = CacheEntryState::STALE;
        if (r.state != CacheEntryState::VALID)
          r.payload.clear ();
        return r;
      }
    }
  }
}
