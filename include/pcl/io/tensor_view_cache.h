/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/features/tensor_descriptor.h>
#include <pcl/io/tensor_view_cache_key.h>
#include <pcl/registration/tensor_registration_report.h>
#include <pcl/registration/tensor_view.h>

#include <cstdint>
#include <string>

namespace pcl
{
  namespace io
  {
    /** \brief Version of the cache files. Raise it when their layout changes, or when preparation or
      * tensor computation changes what it gives for the same input and settings: older entries then
      * read as CacheEntryState::OTHER_VERSION and are made again.
      * \ingroup io
      */
    constexpr std::uint32_t TENSOR_VIEW_CACHE_VERSION = 1;

    /** \brief The two entries of a view: its meshes do not depend on D, its tensors do, so a new D
      * (another set of views) leaves the meshes valid.
      * \ingroup io
      */
    enum class CacheEntryKind : std::uint32_t
    {
      /** M_i and M'_i (PreparedScan), the view's origin and its principal extents. */
      MESHES = 1,
      /** The tensors of M'_i, with the D and the hashTensorParameters() they were computed with. */
      TENSORS = 2,
      /** A pairwise registration of two views (TensorRegistrationReport), keyed by pairCacheKey(). */
      PAIR = 3,
      /** A whole run of pcl_tensor_model (ModelRunRecord), keyed by modelRunKey(). */
      RUN = 4,
      /** Ranking scores of view pairs (PairScoreCache), each keyed by pairScoreKey(). */
      SCORES = 5,
      /** The voxels of a model (IntegrationVolume), keyed by integrationVolumeKey(). */
      VOLUME = 6,
      /** The sensor a scan file was read with (ScanViewpoint), keyed by scanSensorKey(). */
      SENSOR = 7
    };

    /** \brief What a lookup found. Only VALID gives data; any other state leaves the output untouched.
      * \ingroup io
      */
    enum class CacheEntryState
    {
      /** The entry is whole, its checksum matches, and it was made for the key (and D and tensor settings). */
      VALID,
      /** No file. */
      MISSING,
      /** Not an entry, or damaged: bad magic bytes, checksum mismatch, bytes beyond its end, the wrong kind,
        * or content that does not decode. */
      CORRUPT,
      /** The file ends before its header, or before the end its header gives. */
      TRUNCATED,
      /** Whole, but made for another key (or, for tensors, another D or other tensor settings). */
      STALE,
      /** Written with another TENSOR_VIEW_CACHE_VERSION. */
      OTHER_VERSION
    };

    /** \brief "valid", "missing", "corrupt", "truncated", "stale" or "other_version". \ingroup io */
    const char*
    toString (CacheEntryState state);

    /** \brief A folder of prepared views (TensorView), so that a view is meshed once, and its tensors
      * computed once per D, across runs and processes.
      *
      * Each entry is one file `VIEW_ID.meshes.tvc` or `VIEW_ID.tensors.tvc`, laid out little-endian:
      * | offset | field |
      * |---|---|
      * | 0 | magic, 8 bytes: 0x89 'T' 'V' 'C' 'A' '\\r' '\\n' 0x1a |
      * | 8 | u32 version (TENSOR_VIEW_CACHE_VERSION) |
      * | 12 | u32 kind (CacheEntryKind) |
      * | 16 | u64 key.source, u64 key.preparation |
      * | 32 | u64 payload size n |
      * | 40 | payload, n bytes |
      * | 40 + n | u64 ContentHash of bytes [0, 40 + n) |
      *
      * The meshes payload starts with the origin and the principal extents (3 doubles each), then d_res,
      * noise and both meshes (viewpoint, cloud header, PointNormal fields, polygons); the tensors payload
      * with D (3 doubles) and the tensor hash, then every fixed field and both bin vectors of each tensor.
      * Counts are checked against the bytes left before anything is allocated for them.
      *
      * Entries are written through AtomicFileWriter: two processes saving one entry leave one whole file
      * (the last one's), and a reader never sees a partial one. It only stores and loads: what to compute
      * when an entry is not VALID is the caller's choice (pcl_tensor_prepare).
      * \ingroup io
      */
    class TensorViewCache
    {
      public:
        /** \brief A cache in folder \a dir, created (with its parents) if missing.
          * \throw pcl::IOException when it cannot be created or is not a folder */
        explicit TensorViewCache (const std::string& dir);

        /** \brief The folder. */
        const std::string& getDirectory () const { return dir_; }

        /** \brief The file of one entry.
          * \throw pcl::BadArgumentException when \a view_id is not isValidViewId() */
        std::string
        entryPath (const std::string& view_id, CacheEntryKind kind) const;

        /** \brief Store \a view's meshes and origin, with principalExtents() of its fine mesh (Eq. 1 for one view).
          * \throw pcl::BadArgumentException when \a view has no meshes, pcl::IOException when the file cannot be written */
        void
        saveView (const std::string& view_id, const TensorViewCacheKey& key, const pcl::registration::TensorView& view) const;

        /** \brief Load a view's meshes and origin into \a out (its tensors null, its dimensions zero) when VALID.
          * \throw pcl::IOException when the entry exists but cannot be read (permissions, a device error) */
        CacheEntryState
        loadView (const std::string& view_id, const TensorViewCacheKey& key, pcl::registration::TensorView& out) const;

        /** \brief A view's principal extents, for D = the elementwise max over views (Eq. 1,
          * computeObjectDimensions()) without loading its meshes: the whole entry is still read and its
          * frame checked (magic, version, kind, key, size, checksum), but only its first fields are
          * decoded, so meshes that do not decode behind a valid checksum (written by something else
          * than saveView()) are found by loadView() alone. \a extents is set only when VALID.
          * \throw pcl::IOException as loadView() */
        CacheEntryState
        loadExtents (const std::string& view_id, const TensorViewCacheKey& key, Eigen::Vector3d& extents) const;

        /** \brief Store a view's tensors, computed with \a dims and settings of hash \a tensor_hash
          * (hashTensorParameters()). \throw pcl::IOException when the file cannot be written */
        void
        saveTensors (const std::string& view_id, const TensorViewCacheKey& key, const ObjectDimensions& dims,
                     std::uint64_t tensor_hash, const pcl::PointCloud<pcl::TensorDescriptor>& tensors) const;

        /** \brief Load a view's tensors into \a out when VALID: same key, D equal bit for bit to \a dims.D
          * and the same \a tensor_hash; otherwise STALE (or another state) and \a out is untouched.
          * \throw pcl::IOException as loadView() */
        CacheEntryState
        loadTensors (const std::string& view_id, const TensorViewCacheKey& key, const ObjectDimensions& dims,
                     std::uint64_t tensor_hash, pcl::PointCloud<pcl::TensorDescriptor>::Ptr& out) const;

        /** \brief Store the registration of view \a scene_id into \a model_id's frame, made under \a key
          * (pairCacheKey()). \throw pcl::IOException when the file cannot be written */
        void
        savePair (const std::string& model_id, const std::string& scene_id, const TensorViewCacheKey& key,
                  const pcl::registration::TensorRegistrationReport& report) const;

        /** \brief Load a pair's registration into \a out when VALID for \a key.
          * \throw pcl::IOException as loadView() */
        CacheEntryState
        loadPair (const std::string& model_id, const std::string& scene_id, const TensorViewCacheKey& key,
                  pcl::registration::TensorRegistrationReport& out) const;

      private:
        std::string dir_;
    };
  }
}
