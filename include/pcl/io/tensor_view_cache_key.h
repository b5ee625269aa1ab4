/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>

#include <pcl/common/scan_viewpoint.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/tensor_registration_params.h>
#include <pcl/registration/view_pair_ranking.h>
#include <pcl/surface/scan_preparation.h>

#include <cstdint>
#include <string>

namespace pcl
{
  namespace io
  {
    /** \brief What a view's cache entries were made from: the range image and how it was prepared.
      * An entry is used only for the key it was made with (TensorViewCache).
      * \ingroup io
      */
    struct TensorViewCacheKey
    {
      /** \brief The range image: hashFileContents() of its file, or hashPointCloud() of a cloud in memory. */
      std::uint64_t source = 0;
      /** \brief How M_i and M'_i were made from it: hashPreparation(). */
      std::uint64_t preparation = 0;
    };

    /** \brief Keys are equal when both hashes are. */
    inline bool
    operator== (const TensorViewCacheKey& a, const TensorViewCacheKey& b)
    {
      return a.source == b.source && a.preparation == b.preparation;
    }

    /** \brief Keys differ when either hash does. */
    inline bool
    operator!= (const TensorViewCacheKey& a, const TensorViewCacheKey& b)
    {
      return !(a == b);
    }

    /** \brief The source hash of a range image in memory: its width and height and every point's
      * x, y, z by their bit patterns (NaN cells included, so organization counts).
      * \ingroup io
      */
    std::uint64_t
    hashPointCloud (const pcl::PointCloud<pcl::PointXYZ>& cloud);

    /** \brief The preparation hash: every field of \a params and the sensor (model and pose, by bit
      * patterns) that prepareTensorView() meshes the view with.
      * \ingroup io
      */
    std::uint64_t
    hashPreparation (const ScanPreparationParams& params, const ScanViewpoint& viewpoint);

    /** \brief A hash of the settings a view's tensors are computed with besides its meshes and D:
      * those of TensorRegistrationParams that computeViewTensors() passes to pcl::TensorEstimation
      * (grid_size, partners_per_vertex, min_normal_angle, region_growing). The matching and verification
      * settings do not change the tensors and are left out.
      * \ingroup io
      */
    std::uint64_t
    hashTensorParameters (const pcl::registration::TensorRegistrationParams& params);

    /** \brief The key of a pair's registration: both views' keys, D and every setting of
      * TensorRegistrationParams (matching, verification, the hypothesis search, the tensors').
      * \ingroup io
      */
    TensorViewCacheKey
    pairCacheKey (const TensorViewCacheKey& model, const TensorViewCacheKey& scene, const ObjectDimensions& dims,
                  const pcl::registration::TensorRegistrationParams& params);

    /** \brief A hash of everything a ranking score (ViewPairRanking::score()) depends on besides the two
      * views: D, the tensor settings (hashTensorParameters()), the matching thresholds t_r and t_c, the
      * theta_d bin width and \a ranking.
      * \ingroup io
      */
    std::uint64_t
    hashRankingSettings (const ObjectDimensions& dims, const pcl::registration::TensorRegistrationParams& params,
                         const pcl::registration::ViewPairRankingParams& ranking);

    /** \brief The key of a ranking score: both views' keys, taken in an order of their own (the score is
      * symmetric, and a view's index changes from run to run), and \a ranking_settings (hashRankingSettings()).
      * \ingroup io
      */
    TensorViewCacheKey
    pairScoreKey (const TensorViewCacheKey& a, const TensorViewCacheKey& b, std::uint64_t ranking_settings);

    /** \brief A file-name-safe id for the view in file \a path: its stem (characters other than
      * letters, digits, '-', '_' and '.' replaced by '_'; at most 64 of them), '-', and 16 hex digits of
      * the hash of its canonical absolute path, so that views of the same name in two folders, or
      * named through two relative paths, get their own or the same id as they should.
      * \ingroup io
      */
    std::string
    viewIdOf (const std::string& path);

    /** \brief True when \a view_id can name cache entries: 1 to 200 letters, digits, '-', '_' or '.',
      * not starting with '.'.
      * \ingroup io
      */
    bool
    isValidViewId (const std::string& view_id);
  }
}
