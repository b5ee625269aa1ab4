/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/multiview_point_to_plane_icp.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/search/bounded_nearest_search.h>
#include "../common/parallel_for.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

namespace pcl
{
  namespace registration
  {
    namespace
    {
      using Vector6d = Eigen::Matrix<double, 6, 1>;

      /** One view's search structure, usable partners and sample. */
      struct IcpView
      {
        const ScanMesh* mesh = nullptr;
        std::shared_ptr<pcl::BoundedNearestSearch> search;
        std::vector<bool> usable;  ///< may be a partner: has a normal (and is not on the boundary)
        std::vector<int> sample;   ///< evenly spaced usable vertices
      };

      bool
      hasNormal (const pcl::PointNormal& p)
      {
        const Eigen::Vector3f n = p.getNormalVector3fMap ();
        return n.allFinite () && n.squaredNorm () > 0.0f;
      }

      IcpView
      makeIcpView (const ScanMesh& mesh, bool skip_boundary, int sample_points, double max_distance)
      {
        IcpView v;
        v.mesh = &mesh;
        v.search = std::make_shared<pcl::BoundedNearestSearch> (static_cast<float> (max_distance));
        v.search->setInputCloud (*mesh.cloud);
        const std::vector<bool> boundary = skip_boundary ? meshBoundaryVertices (mesh) : std::vector<bool> (mesh.cloud->size (), false);
        v.usable.resize (mesh.cloud->size ());
        std::vector<int> candidates;
        for (std::size_t i = 0; i < mesh.cloud->size (); ++i)
        {
          v.usable[i] = hasNormal ((*mesh.cloud)[i]) && !boundary[i];
          if (v.usable[i])
            candidates.push_back (static_cast<int> (i));
        }
        const std::size_t n = std::min (candidates.size (), static_cast<std::size_t> (std::max (sample_points, 1)));
        for (std::size_t k = 0; k < n; ++k)
          v.sample.push_back (candidates[k * candidates.size () / n]);
        return v;
      }

      using Matrix12d = Eigen::Matrix<double, 12, 12>;
      using Vector12d = Eigen::Matrix<double, 12, 1>;

      /** The normal equations of one pair of views, both directions, over both views' small motions
        * (first view's six unknowns, then the second's). Pairs are independent, so each is built on
        * its own thread and added to the joint system in pair order: the same sums at any thread count. */
      struct PairSystem
      {
        Matrix12d h = Matrix12d::Zero ();
        Vector12d g = Vector12d::Zero ();
        std::size_t pairs = 0;
        double sum2 = 0.0;
      };

      /** Pairs sampled points of view \a a with their nearest partners on view \a b and adds their
        * linearised point-to-plane distances; \a a_first: a's unknowns are the first six of \a system.
        * Poses are about the centre (see multiviewPointToPlaneIcp). \a hints: each sampled point's last
        * partner, so that the next iteration's search starts from it (sized here on first use). */
      void
      addPairTerms (const IcpView& a, const IcpView& b, const Eigen::Affine3d& pose_a, const Eigen::Affine3d& pose_b,
                    bool a_first, double max_distance, double min_cos, std::vector<std::int32_t>& hints, PairSystem& system)
      {
        const Eigen::Affine3d a_to_b = pose_b.inverse () * pose_a;
        const float radius = static_cast<float> (max_distance);
        const int offset_a = a_first ? 0 : 6, offset_b = a_first ? 6 : 0;
        float d2;
        hints.resize (a.sample.size (), -1);
        for (std::size_t k = 0; k < a.sample.size (); ++k)
        {
          const pcl::PointNormal& p = (*a.mesh->cloud)[a.sample[k]];
          const Eigen::Vector3d p_a = p.getVector3fMap ().cast<double> ();
          const int index = b.search->nearest ((a_to_b * p_a).cast<float> (), radius, d2, hints[k]);
          if (index < 0 || !b.usable[index])
            continue;
          const pcl::PointNormal& q = (*b.mesh->cloud)[index];
          const Eigen::Vector3d n = pose_b.linear () * q.getNormalVector3fMap ().cast<double> ();
          if ((pose_a.linear () * p.getNormalVector3fMap ().cast<double> ()).dot (n) < min_cos)
            continue;
          const Eigen::Vector3d x = pose_a * p_a;
          const Eigen::Vector3d y = pose_b * q.getVector3fMap ().cast<double> ();
          const double r = n.dot (x - y);
          // d r / d (rotation, translation) of a small motion of each view, applied in the common frame.
          Vector12d j;
          j.segment<3> (offset_a) = x.cross (n);
          j.segment<3> (offset_a + 3) = n;
          j.segment<3> (offset_b) = -y.cross (n);
          j.segment<3> (offset_b + 3) = -n;
          system.g.noalias () -= j * r;
          system.h.noalias () += j * j.transpose ();
          system.sum2 += r * r;
          ++system.pairs;
        }
      }

      /** The normal equations of all poses together, over the unknowns of the moving views: sparse,
        * since each pair couples two views only, so that the solve grows with the pairs, not with the
        * cube of the views (a dense 6N x 6N factorisation dominated the step at 200 views). */
      struct JointSystem
      {
        explicit JointSystem (int unknowns) : size (6 * unknowns), g (Eigen::VectorXd::Zero (6 * unknowns)) {}

        int size;
        std::vector<Eigen::Triplet<double>> h;
        Eigen::VectorXd g;
        std::size_t pairs = 0;
        double sum2 = 0.0;

        /** Add one pair's equations; a view without unknowns (the fixed one, var < 0) drops out. */
        void
        add (const PairSystem& pair, int var_a, int var_b)
        {
          const int vars[2] = {var_a, var_b};
          for (int u = 0; u < 2; ++u)
          {
            if (vars[u] < 0)
              continue;
            g.segment<6> (6 * vars[u]) += pair.g.segment<6> (6 * u);
            for (int w = 0; w < 2; ++w)
              if (vars[w] >= 0)
                for (int r = 0; r < 6; ++r)
                  for (int c = 0; c < 6; ++c)
                    h.emplace_back (6 * vars[u] + r, 6 * vars[w] + c, pair.h (6 * u + r, 6 * w + c));
          }
          sum2 += pair.sum2;
          pairs += pair.pairs;
        }

        /** The small motions of all moving views (NaN when the system cannot be solved). A view left
          * without pairs would make it singular: a tiny damping keeps it still. */
        Eigen::VectorXd
        solve () const
        {
          Eigen::SparseMatrix<double> m (size, size);
          m.setFromTriplets (h.begin (), h.end ());
          const double damping = 1e-9 * std::max (m.diagonal ().maxCoeff (), 1e-12);
          for (int i = 0; i < size; ++i)
            m.coeffRef (i, i) += damping;
          const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt (m);
          if (ldlt.info () != Eigen::Success)
            return Eigen::VectorXd::Constant (size, std::numeric_limits<double>::quiet_NaN ());
          return ldlt.solve (g);
        }
      };

      /** Which views are in one of \a pairs. \throw pcl::BadArgumentException on a pair that is not two given views */
      std::vector<char>
      viewsInPairs (const std::vector<const ScanMesh*>& views, const ViewPairs& pairs, const char* caller)
      {
        const int n = static_cast<int> (views.size ());
        std::vector<char> in_pair (views.size (), 0);
        for (const auto& p : pairs)
        {
          if (p.first < 0 || p.first >= n || p.second < 0 || p.second >= n || p.first == p.second || !views[p.first] || !views[p.second])
            PCL_TENSOR_THROW (BadArgumentException, caller << ": pair (" << p.first << ", " << p.second << ") is not a pair of two given views");
          in_pair[p.first] = in_pair[p.second] = 1;
        }
        return in_pair;
      }

      Eigen::Affine3d
      smallMotion (const Vector6d& x)
      {
        Eigen::Affine3d m = Eigen::Affine3d::Identity ();
        const Eigen::Vector3d w = x.head<3> ();
        if (w.norm () > 0.0)
          m.linear () = Eigen::AngleAxisd (w.norm (), w.normalized ()).toRotationMatrix ();
        m.translation () = x.tail<3> ();
        return m;
      }

      /** The centroid of every sample in the initial common frame: the rotations of the joint
        * system are taken about it, which keeps the system well conditioned for views whose frame
        * origin is far from the object (a sensor's frame). */
      Eigen::Vector3d
      sampleCentre (const std::vector<IcpView>& views, const ViewPoses& poses)
      {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
        std::size_t n = 0;
        for (std::size_t i = 0; i < views.size (); ++i)
          for (const int s : views[i].sample)
          {
            sum += poses[i] * (*views[i].mesh->cloud)[s].getVector3fMap ().cast<double> ();
            ++n;
          }
        return n > 0 ? Eigen::Vector3d (sum / static_cast<double> (n)) : Eigen::Vector3d::Zero ();
      }
    }

    MultiviewIcpResult
    multiviewPointToPlaneIcp (const std::vector<const ScanMesh*>& views, const ViewPoses& initial, const ViewPairs& pairs,
                              int fixed, double resolution, const MultiviewIcpParams& params,
                              const MultiviewIcpProgress& progress, unsigned threads)
    {
      if (fixed < 0 || fixed >= static_cast<int> (views.size ()))
        PCL_TENSOR_THROW (BadArgumentException, "multiview ICP needs a fixed view among the views");
      std::vector<bool> still (views.size (), false);
      still[fixed] = true;
      return multiviewPointToPlaneIcp (views, initial, pairs, still, resolution, params, progress, threads);
    }

    MultiviewIcpResult
    multiviewPointToPlaneIcp (const std::vector<const ScanMesh*>& views, const ViewPoses& initial, const ViewPairs& pairs,
                              const std::vector<bool>& fixed, double resolution, const MultiviewIcpParams& params,
                              const MultiviewIcpProgress& progress, unsigned threads)
    {
      const int n = static_cast<int> (views.size ());
      if (initial.size () != views.size () || fixed.size () != views.size () || std::find (fixed.begin (), fixed.end (), true) == fixed.end ())
        PCL_TENSOR_THROW (BadArgumentException, "multiview ICP needs one pose and one flag per view, and a fixed view among them");
      if (!(resolution > 0.0) || !(params.max_distance > 0.0) || params.max_iterations < 0)
        PCL_TENSOR_THROW (BadArgumentException, "multiview ICP needs a positive resolution and pairing distance");
      const std::vector<char> in_pair = viewsInPairs (views, pairs, "multiview ICP");
      // Unknowns: 6 per view that is in a pair and is not fixed.
      std::vector<int> var (n, -1);
      int unknowns = 0;
      for (int i = 0; i < n; ++i)
        if (in_pair[i] && !fixed[i])
          var[i] = unknowns++;

      std::vector<IcpView> icp_views (n);
      pcl::detail::parallelFor (static_cast<std::size_t> (n), threads, [&] (std::size_t i) {
        if (in_pair[i])
          icp_views[i] = makeIcpView (*views[i], params.skip_boundary, params.sample_points, params.max_distance * resolution);
      });

      MultiviewIcpResult result;
      result.poses = initial;
      const Eigen::Vector3d centre = sampleCentre (icp_views, initial);
      const Eigen::Translation3d to_centre (-centre);
      ViewPoses centred (n);
      for (int i = 0; i < n; ++i)
        centred[i] = to_centre * initial[i];

      const double max_distance = params.max_distance * resolution;
      const double min_cos = std::cos (params.max_normal_angle * M_PI / 180.0);
      std::vector<std::array<std::vector<std::int32_t>, 2>> hints (pairs.size ());
      for (int it = 0; it < params.max_iterations && unknowns > 0; ++it)
      {
        JointSystem system (unknowns);
        std::vector<PairSystem> pair_systems (pairs.size ());
        pcl::detail::parallelFor (pairs.size (), threads, [&] (std::size_t k) {
          const int i = pairs[k].first, j = pairs[k].second;
          addPairTerms (icp_views[i], icp_views[j], centred[i], centred[j], true, max_distance, min_cos, hints[k][0], pair_systems[k]);
          addPairTerms (icp_views[j], icp_views[i], centred[j], centred[i], false, max_distance, min_cos, hints[k][1], pair_systems[k]);
        });
        for (std::size_t k = 0; k < pairs.size (); ++k)
          system.add (pair_systems[k], var[pairs[k].first], var[pairs[k].second]);
        if (system.pairs == 0)
          break;
        const double rms = std::sqrt (system.sum2 / static_cast<double> (system.pairs));
        if (it == 0)
          result.rms_before = rms;
        result.rms_after = rms;
        result.pairs = system.pairs;
        // A view left without pairs would make the system singular: a tiny damping keeps it still.
        const Eigen::VectorXd x = system.solve ();
        if (!x.allFinite ())
          break;
        double max_rotation = 0.0, max_translation = 0.0;
        for (int i = 0; i < n; ++i)
          if (var[i] >= 0)
          {
            const Vector6d xi = x.segment<6> (6 * var[i]);
            centred[i] = smallMotion (xi) * centred[i];
            max_rotation = std::max (max_rotation, xi.head<3> ().norm () * 180.0 / M_PI);
            max_translation = std::max (max_translation, xi.tail<3> ().norm () / resolution);
          }
        result.iterations = it + 1;
        if (progress)
          progress (it + 1, params.max_iterations);
        if (max_rotation < params.min_rotation && max_translation < params.min_translation)
          break;
      }
      for (int i = 0; i < n; ++i)
        if (var[i] >= 0)
          result.poses[i] = Eigen::Translation3d (centre) * centred[i];  // the others keep theirs to the bit
      return result;
    }

    ViewPairs
    findOverlappingViews (const std::vector<const ScanMesh*>& views, const ViewPoses& poses, const std::vector<bool>& use,
                          double resolution, double max_distance, double min_fraction, int sample_points, unsigned threads,
                          std::vector<double>* fractions)
    {
      if (!use.empty () && use.size () != views.size ())
        PCL_TENSOR_THROW (BadArgumentException, "findOverlappingViews needs one flag per view");
      ViewPairs candidates;
      for (std::size_t i = 0; i < views.size (); ++i)
        for (std::size_t j = i + 1; j < views.size (); ++j)
          if (views[i] && views[j] && (use.empty () || (use[i] && use[j])))
            candidates.emplace_back (static_cast<int> (i), static_cast<int> (j));
      return selectOverlappingPairs (views, poses, candidates, resolution, max_distance, min_fraction, sample_points, threads,
                                   fractions);
    }

    ViewPairs
    selectOverlappingPairs (const std::vector<const ScanMesh*>& views, const ViewPoses& poses, const ViewPairs& candidates,
                          double resolution, double max_distance, double min_fraction, int sample_points, unsigned threads,
                          std::vector<double>* fractions)
    {
      const int n = static_cast<int> (views.size ());
      if (poses.size () != views.size ())
        PCL_TENSOR_THROW (BadArgumentException, "findOverlappingViews needs one pose per view");
      const std::vector<char> used = viewsInPairs (views, candidates, "selectOverlappingPairs");
      std::vector<IcpView> icp_views (n);
      pcl::detail::parallelFor (static_cast<std::size_t> (n), threads, [&] (std::size_t i) {
        if (used[i])
          icp_views[i] = makeIcpView (*views[i], false, sample_points, max_distance * resolution);
      });
      const float radius = static_cast<float> (max_distance * resolution);
      std::vector<double> overlap (candidates.size (), 0.0);
      pcl::detail::parallelFor (candidates.size (), threads, [&] (std::size_t k) {
          const int i = candidates[k].first, j = candidates[k].second;
          // The smaller view's sample against the larger view.
          const bool i_smaller = views[i]->cloud->size () <= views[j]->cloud->size ();
          const IcpView& a = icp_views[i_smaller ? i : j];
          const IcpView& b = icp_views[i_smaller ? j : i];
          const Eigen::Affine3d a_to_b = poses[i_smaller ? j : i].inverse () * poses[i_smaller ? i : j];
          std::size_t near = 0;
          for (const int s : a.sample)
          {
            const Eigen::Vector3f query = (a_to_b * (*a.mesh->cloud)[s].getVector3fMap ().cast<double> ()).cast<float> ();
            near += b.search->anyWithin (query, radius) ? 1 : 0;
          }
          overlap[k] = a.sample.empty () ? 0.0 : static_cast<double> (near) / static_cast<double> (a.sample.size ());
      });
      ViewPairs pairs;
      if (fractions)
        fractions->clear ();
      for (std::size_t k = 0; k < candidates.size (); ++k)
        if (overlap[k] > 0.0 && overlap[k] >= min_fraction)
        {
          pairs.push_back (candidates[k]);
          if (fractions)
            fractions->push_back (overlap[k]);
        }
      return pairs;
    }
  }
}
