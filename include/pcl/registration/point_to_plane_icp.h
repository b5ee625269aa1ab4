/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/pcl_macros.h>
#include <pcl/point_cloud.h>
#include <pcl/search/bounded_nearest_search.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/StdVector>

#include <functional>
#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief Settings of pointToPlaneIcp(). */
    struct PointToPlaneIcpParams
    {
      int max_iterations = 30;          ///< iterations at most
      double max_distance = 0.0;        ///< pairs farther apart are not used (required, > 0)
      /** Coarse to fine: when positive and below max_distance, ICP runs again from its last pose with
        * the distance halved, down to this one (8, 4, 2 from 8 to 2), each stage with max_iterations. A
        * wide first stage reaches poses a single tensor match leaves several degrees off; a tight last one
        * keeps the views' parts that do not overlap from pulling the pose. 0: one stage. */
      double final_distance = 0.0;
      /** Pairs whose normals (the source's turned by the pose) differ by more than this angle, radians,
        * are not used: Rusinkiewicz and Levoy's compatible normals. At a sharp edge or on a thin part a
        * point's nearest neighbour lies on another face, whose plane pulls the pose away from the
        * truth. Pi (default): every pair is used. A pair whose source has no normal is used. */
      double max_normal_angle = M_PI;
      double min_rotation = 1e-5;       ///< stop when an update turns less than this (radians) ...
      double min_translation = 0.0;     ///< ... and moves less than this
      /** Stages before the last only have to bring the pose within reach of the next one, so they
        * stop at this many times min_rotation and min_translation (1: every stage converges as fully
        * as the last). The default 100 leaves the final pose as it was, since the last stage still
        * converges fully (doc/design.md#own-point-to-plane-icp). */
      double coarse_stage_tolerance = 100.0;
      /** A stage before the last that ends with fewer pairs than this ends the refinement (0: never).
        * A later stage pairs within a smaller distance from about the same pose, so it cannot find the
        * pairs this one lacked; a caller that needs so many close pairs spares the stages that would
        * only confirm their absence. */
      std::size_t min_pairs = 0;
      /** A stage k stages before the last pairs only every (coarse_stage_step^k)-th source point (1:
        * every stage pairs them all). A coarse stage pairs within a wide distance, where each query
        * scans many cells, and only has to bring the pose within reach of the next stage; the last
        * stage pairs every point, so the final pose rests on them all. Pair counts (min_pairs,
        * PointToPlaneIcpResult::pairs) are scaled to the whole source. */
      int coarse_stage_step = 1;
      /** Called when a stage before the last ends, with the stage's index and pose: false ends the
        * refinement there (PointToPlaneIcpResult::abandoned). A caller that knows the pose to be one
        * from which an earlier run went on and failed spares the stages that would fail the same way:
        * from nearly the same pose, the same stage takes nearly the same path. Empty: never. */
      std::function<bool (std::size_t stage, const Eigen::Matrix4f& pose)> continue_after_stage;
    };

    /** \brief What pointToPlaneIcp() converged to. */
    struct PointToPlaneIcpResult
    {
      Eigen::Matrix4f transform = Eigen::Matrix4f::Identity ();
      int iterations = 0;
      bool stopped_early = false;  ///< a stage ended below min_pairs: the later stages did not run
      bool abandoned = false;      ///< continue_after_stage ended the refinement: the later stages did not run
      /** The pose at the end of each stage that ran, in order. */
      std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> stage_transforms;
      std::size_t pairs = 0;     ///< pairs used in the last iteration (scaled to the whole source in a subsampled stage)
      double rms = 0.0;          ///< RMS point-to-plane distance of those pairs
    };

    /** \brief Point-to-plane ICP (Chen and Medioni's error, in the variant of Rusinkiewicz and Levoy,
      * 2001, that Section 4.1 of Mian et al. uses): each iteration pairs every source point with its
      * nearest target point, drops pairs farther than max_distance, whose target has no normal
      * (NaN or zero) or whose normals differ by more than max_normal_angle, and solves the linearised
      * point-to-plane least squares for a small rotation and a translation.
      * \param[in] source points to move (e.g. a sample of the scene)
      * \param[in] target points with normals (the model), searched through \a search
      * \param[in] search the nearest-neighbour search built on \a target (best with cells near
      *            \a params.max_distance)
      * \param[in] initial the starting transform of the source
      * \param[in] params stopping rules and the pairing distances
      * \return the pose after the last stage; its iterations are those of every stage
      * \ingroup registration
      */
    PointToPlaneIcpResult
    pointToPlaneIcp (const pcl::PointCloud<pcl::PointNormal>& source, const pcl::PointCloud<pcl::PointNormal>& target,
                     const pcl::BoundedNearestSearch& search, const Eigen::Matrix4f& initial,
                     const PointToPlaneIcpParams& params);
  }
}
