/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/correspondence_rejection_tensor_verification.h>
#include <pcl/registration/tensor_match.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/transforms.h>
#include <pcl/registration/point_to_plane_icp.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace pcl
{
  namespace registration
  {
    std::string
    toString (TensorVerificationStage stage)
    {
      switch (stage)
      {
        case TensorVerificationStage::PASSED: return "passed";
        case TensorVerificationStage::COARSE_DIMENSIONS: return "coarse_dimensions";
        case TensorVerificationStage::COARSE_OVERLAP: return "coarse_overlap";
        case TensorVerificationStage::FINE_OVERLAP: return "fine_overlap";
        case TensorVerificationStage::FINE_DIMENSIONS: return "fine_dimensions";
        case TensorVerificationStage::FREE_SPACE: return "free_space";
      }
      return "unknown";
    }

    void
    CorrespondenceRejectorTensorVerification::setModel (const shared_ptr<const PreparedScan>& scan, const TensorCloudConstPtr& tensors,
                                                        const RangeViewProjectionMemo::Ptr& projections)
    {
      model_ = scan;
      model_projections_ = projections;
      model_tensors_ = tensors;
      prepared_ = false;
    }

    void
    CorrespondenceRejectorTensorVerification::setScene (const shared_ptr<const PreparedScan>& scan, const TensorCloudConstPtr& tensors,
                                                        const RangeViewProjectionMemo::Ptr& projections)
    {
      scene_ = scan;
      scene_projections_ = projections;
      scene_tensors_ = tensors;
      prepared_ = false;
    }

    void
    CorrespondenceRejectorTensorVerification::setParams (const TensorVerificationParams& params)
    {
      const auto positive = [] (double v) { return std::isfinite (v) && v > 0.0; };
      const auto& p = params;
      // With a zero n_c or distance every hypothesis would count its correspondences against zero.
      if (!(p.correspondence_fraction > 0.0 && p.correspondence_fraction <= 1.0))
        PCL_TENSOR_THROW (BadArgumentException, "verification: n_c fraction must be in (0, 1], got " << p.correspondence_fraction);
      if (!positive (p.coarse_distance) || !positive (p.fine_distance) || !positive (p.icp_max_distance)
          || !positive (p.icp_final_distance) || p.icp_final_distance > p.icp_max_distance)
        PCL_TENSOR_THROW (BadArgumentException, "verification: distances must be positive (ICP's final one at most its first), got coarse "
                          << p.coarse_distance << ", fine " << p.fine_distance << ", ICP " << p.icp_max_distance << " to "
                          << p.icp_final_distance);
      if (!(p.coarse_dimension_fraction >= 0.0) || !(p.fine_dimension_tolerance >= 0.0) || !(p.fine_dimension_fraction >= 0.0) ||
          !std::isfinite (p.coarse_dimension_fraction) || !std::isfinite (p.fine_dimension_tolerance) ||
          !std::isfinite (p.fine_dimension_fraction))
        PCL_TENSOR_THROW (BadArgumentException, "verification: dimension tolerances must be finite and non-negative");
      if (!(p.empty_space_margin >= 0.0) || !std::isfinite (p.empty_space_margin))
        PCL_TENSOR_THROW (BadArgumentException, "verification: the empty-space margin must be finite and non-negative, got "
                          << p.empty_space_margin);
      if (!positive (p.free_space_distance) || !(p.free_space_fraction >= 0.0 && p.free_space_fraction <= 1.0))
        PCL_TENSOR_THROW (BadArgumentException, "verification: free-space distance must be positive and its fraction in [0, 1], got "
                          << p.free_space_distance << " and " << p.free_space_fraction);
      if (p.checked_dimensions < 1 || p.checked_dimensions > 3 || p.icp_iterations < 0 || p.sample_points < 1 || p.icp_coarse_stage_step < 1
          || !(p.icp_max_normal_angle >= 0.0 && p.icp_max_normal_angle <= 180.0))
        PCL_TENSOR_THROW (BadArgumentException, "verification: checked dimensions must be 1..3, ICP iterations >= 0, sample points >= 1, "
                          "the ICP coarse-stage step >= 1 and the ICP normal angle in [0, 180]");
      // Only the samples and the views' projections depend on the parameters: else what prepare() built stays.
      prepared_ = prepared_ && p.sample_points == params_.sample_points && p.empty_space_margin == params_.empty_space_margin;
      params_ = params;
    }

    namespace
    {
      /** The samples' fine count must reach this share of 2 n_c before every point is counted: a little
        * below 1, as a sample's count varies about the view's. */
      constexpr double kSampledFineShare = 0.8;

      /** An even, deterministic sample of about \a n points: every k-th point. */
      pcl::PointCloud<pcl::PointNormal>::Ptr
      evenSample (const pcl::PointCloud<pcl::PointNormal>& cloud, int n)
      {
        const std::size_t step = std::max<std::size_t> (1, cloud.size () / static_cast<std::size_t> (std::max (1, n)));
        pcl::PointCloud<pcl::PointNormal>::Ptr sample (new pcl::PointCloud<pcl::PointNormal>);
        for (std::size_t i = 0; i < cloud.size (); i += step)
          sample->push_back (cloud[i]);
        return sample;
      }

      /** The inverse of a rigid transform, exact up to rounding (no general inversion). */
      Eigen::Matrix4f
      inverseRigid (const Eigen::Matrix4f& t)
      {
        Eigen::Matrix4f inv = Eigen::Matrix4f::Identity ();
        inv.topLeftCorner<3, 3> () = t.topLeftCorner<3, 3> ().transpose ();
        inv.topRightCorner<3, 1> () = -inv.topLeftCorner<3, 3> () * t.topRightCorner<3, 1> ();
        return inv;
      }
    }

    double
    CorrespondenceRejectorTensorVerification::scenePairsNeeded (double correspondences) const
    {
      // correspondences() scales the sample's count to the view and, counting both views, doubles the
      // smaller of the two.
      const double per_view = params_.count_both_views ? 0.5 * correspondences : correspondences;
      return per_view * static_cast<double> (scene_sample_->size ()) / static_cast<double> (scene_->fine.cloud->size ());
    }

    double
    CorrespondenceRejectorTensorVerification::requiredCorrespondences () const
    {
      return params_.correspondence_fraction *
             static_cast<double> (std::min (model_->fine.cloud->size (), scene_->fine.cloud->size ()));
    }

    std::size_t
    CorrespondenceRejectorTensorVerification::icpMinPairs () const
    {
      return static_cast<std::size_t> (std::floor (scenePairsNeeded (kSampledFineShare * 2.0 * requiredCorrespondences ())));
    }

    double
    CorrespondenceRejectorTensorVerification::getResolution () const
    {
      return model_ && scene_ ? 0.5 * (model_->resolution + scene_->resolution) : 0.0;
    }

    void
    CorrespondenceRejectorTensorVerification::prepare ()
    {
      if (prepared_)
        return;
      if (!model_ || !scene_ || model_->fine.cloud->empty () || scene_->fine.cloud->empty ())
        PCL_TENSOR_THROW (BadArgumentException, "verification needs the prepared model and scene views");
      // Cells of 2 d_res: every query asks for 1 to 8 d_res (see BoundedNearestSearch).
      const float cell = static_cast<float> (2.0 * getResolution ());
      model_search_ = pcl::BoundedNearestSearch (cell);
      model_search_.setInputCloud (*model_->fine.cloud);
      model_view_.reset ();
      scene_view_.reset ();
      model_empty_view_.reset ();
      scene_empty_view_.reset ();
      empty_views_margin_ = 0.0;
      // The scene's search and the model's sample serve count_both_views and covisibility().
      scene_sample_ = evenSample (*scene_->fine.cloud, params_.sample_points);
      scene_search_ = pcl::BoundedNearestSearch (cell);
      scene_search_.setInputCloud (*scene_->fine.cloud);
      model_sample_ = evenSample (*model_->fine.cloud, params_.sample_points);
      model_fine_extents_ = ViewExtents (*model_->fine.cloud);
      scene_fine_extents_ = ViewExtents (*scene_->fine.cloud);
      model_reduced_extents_ = ViewExtents (*model_->reduced.cloud);
      scene_reduced_extents_ = ViewExtents (*scene_->reduced.cloud);
      prepared_ = true;
    }

    double
    CorrespondenceRejectorTensorVerification::correspondences (const PointCloudN& scene_points, const PointCloudN& model_points,
                                                              const Eigen::Matrix4f& t, double radius) const
    {
      // Counts on a sample stand for the whole view; on the whole view the scale is exactly 1.
      const auto scaled = [] (std::size_t count, const PointCloudN& points, const PointCloudN& view) {
        return static_cast<double> (count) * static_cast<double> (view.size ()) / static_cast<double> (points.size ());
      };
      const double scene = scaled (countCorrespondences (scene_points, t, model_search_, radius), scene_points, *scene_->fine.cloud);
      if (!params_.count_both_views)
        return scene;
      const double model = scaled (countCorrespondences (model_points, inverseRigid (t), scene_search_, radius), model_points,
                                   *model_->fine.cloud);
      return 2.0 * std::min (scene, model);  // each view must bring its half (TensorVerificationParams)
    }

    std::size_t
    CorrespondenceRejectorTensorVerification::countCorrespondences (const PointCloudN& cloud, const Eigen::Matrix4f& t,
                                                                   const pcl::BoundedNearestSearch& search,
                                                                   double radius)
    {
      const float r = static_cast<float> (radius);
      std::size_t count = 0;
      std::int32_t hint = -1;
      for (const auto& p : cloud)
        count += search.anyWithin ((t * p.getVector4fMap ()).head<3> (), r, hint) ? 1 : 0;
      return count;
    }

    namespace
    {
      /** The free-space z-buffers' pixels per d_res. One per d_res is a little faster but refuses
        * noisy views: a pixel then holds the depth of one noisy triangle rather than of a local mean
        * (doc/design.md#free-space-check). */
      constexpr double kZBufferPixelsPerResolution = 2.0;

      /** A point this many margins in front of the surface on its line of sight, with a surface at its own
        * depth beside that line, lies on an occlusion boundary (doc/design.md#free-space-check). */
      constexpr double kOcclusionDepthMargins = 4.0;

      /** Whether \a p (scan frame of \a to), \a distance in front of the surface on its line of sight,
        * has a surface of \a to no farther than itself (within \a margin) beside that line (in the
        * z-buffer tiles that a box of \a margin about it covers, a few d_res): a foreground edge that a
        * pose slightly off puts it beside. Only deep violations are excused; a shallow one is a surface
        * out of place, not an edge missed. */
      bool
      besideOcclusionBoundary (const Eigen::Vector3f& p, float distance, const RangeViewProjection& to, double margin)
      {
        if (distance <= kOcclusionDepthMargins * margin)
          return false;
        const Eigen::Vector3f s = to.getScanToSensor () * p;
        const Eigen::Vector3f half = Eigen::Vector3f::Constant (static_cast<float> (margin));
        float nearest = 0.0f, farthest = 0.0f;
        return to.depthRange (s - half, s + half, nearest, farthest) && nearest <= s.z () + static_cast<float> (margin);
      }

      /** Where a point lies against a view's free space. */
      enum class FreeSpace { UNSEEN, CONSISTENT, VIOLATING };

      /** Where \a p (scan frame of \a to) lies: unseen when \a to's sensor saw no trusted surface on its
        * line of sight (borders and grazing views, weight < 0.3, are not trusted) and no empty space;
        * violating when more than \a margin in front of that surface (and not beside an occlusion
        * boundary) or where the sensor saw empty space. Points behind the surface are consistent: that
        * sensor could not see them. */
      FreeSpace
      freeSpaceAt (const Eigen::Vector3f& p, const RangeViewProjection& to, double margin)
      {
        constexpr float kMinWeight = 0.3f;
        RangeViewProjection::Sample sample;
        if (to.sample (p, sample))
        {
          if (sample.weight < kMinWeight)
            return FreeSpace::UNSEEN;
          const bool in_front = sample.distance > margin && !besideOcclusionBoundary (p, sample.distance, to, margin);
          return in_front ? FreeSpace::VIOLATING : FreeSpace::CONSISTENT;
        }
        return to.seenEmpty (p) ? FreeSpace::VIOLATING : FreeSpace::UNSEEN;
      }

      /** Whether at least a quarter of the points of \a from within \a margin of its point \a i (in its
        * own view, \a from_search) violate \a to's free space too: a surface out of place, not a noisy
        * point. Independent noise that puts 2% of the points past the margin gives a quarter of 12
        * neighbours less than once in 500; a surface just past the margin, half of whose points are, nearly
        * always. A point without neighbours counts. */
      bool
      coherentViolation (const pcl::PointCloud<pcl::PointNormal>& from, std::size_t i, const pcl::BoundedNearestSearch& from_search,
                         const Eigen::Matrix4f& t, const RangeViewProjection& to, double margin)
      {
        std::vector<int> neighbours;
        from_search.radiusSearch (from[i].getVector3fMap (), static_cast<float> (margin), neighbours);
        std::size_t others = 0, violating = 0;
        for (const int j : neighbours)
          if (static_cast<std::size_t> (j) != i)
          {
            ++others;
            violating += freeSpaceAt ((t * from[j].getVector4fMap ()).head<3> (), to, margin) == FreeSpace::VIOLATING ? 1 : 0;
          }
        return 4 * violating >= others;
      }

      /** Of the points of \a from (under \a t) that \a to's sensor saw (freeSpaceAt()), the fraction that
        * violate its free space coherently (coherentViolation()). Independent noise puts single points
        * past any margin; a misplaced surface puts whole patches there. */
      double
      violationFraction (const pcl::PointCloud<pcl::PointNormal>& from, const pcl::BoundedNearestSearch& from_search,
                         const Eigen::Matrix4f& t, const RangeViewProjection& to, double margin, double stop_above)
      {
        constexpr std::size_t kSamples = 4000;
        constexpr std::size_t kMinSeen = 50;  // fewer: too little seen by both to judge
        const std::size_t step = std::max<std::size_t> (1, from.size () / kSamples);
        // Once violations outnumber stop_above of all samples (and kMinSeen), the fraction of those seen exceeds it.
        const double samples = static_cast<double> ((from.size () + step - 1) / step);
        const double stop = std::max (stop_above * samples, static_cast<double> (kMinSeen));
        std::size_t seen = 0, violating = 0;
        for (std::size_t i = 0; i < from.size (); i += step)
        {
          const FreeSpace f = freeSpaceAt ((t * from[i].getVector4fMap ()).head<3> (), to, margin);
          if (f == FreeSpace::UNSEEN)
            continue;
          ++seen;
          violating += f == FreeSpace::VIOLATING && coherentViolation (from, i, from_search, t, to, margin) ? 1 : 0;
          if (static_cast<double> (violating) > stop)
            return static_cast<double> (violating) / samples;
        }
        return seen < kMinSeen ? 0.0 : static_cast<double> (violating) / static_cast<double> (seen);
      }
    }

    RangeViewProjectionMemo::Projection
    CorrespondenceRejectorTensorVerification::projectView (const shared_ptr<const PreparedScan>& view,
                                                           const RangeViewProjectionMemo::Ptr& memo, double empty_margin) const
    {
      // The z-buffers are built only for hypotheses that got this far: once per view with a memo,
      // else once per pair of views. They depend on the view and on the empty-space margin alone.
      const int pixels = static_cast<int> (std::ceil (empty_margin * kZBufferPixelsPerResolution));
      const auto make = [&] () -> RangeViewProjectionMemo::Projection {
        auto projection = std::make_shared<RangeViewProjection> (view->fine, 3.0, kZBufferPixelsPerResolution, 16u << 20, view->resolution);
        if (empty_margin > 0.0)
          projection->markEmptySpace (pixels);
        return projection;
      };
      return memo ? memo->get (view, empty_margin > 0.0 ? pixels : -1, make) : make ();
    }

    void
    CorrespondenceRejectorTensorVerification::projectViews ()
    {
      if (!model_view_)
        model_view_ = projectView (model_, model_projections_, params_.empty_space_margin);
      if (!scene_view_)
        scene_view_ = projectView (scene_, scene_projections_, params_.empty_space_margin);
    }

    double
    CorrespondenceRejectorTensorVerification::getFreeSpaceMargin () const
    {
      return std::max (params_.free_space_distance * getResolution (), 3.0 * std::hypot (model_->noise, scene_->noise));
    }

    double
    CorrespondenceRejectorTensorVerification::freeSpaceViolation (const Eigen::Matrix4f& t, double margin)
    {
      prepare ();
      projectViews ();
      return violation (t, margin, *model_view_, *scene_view_);
    }

    double
    CorrespondenceRejectorTensorVerification::emptySpaceViolation (const Eigen::Matrix4f& t, double empty_margin)
    {
      if (!(empty_margin > 0.0))
        PCL_TENSOR_THROW (BadArgumentException, "the empty-space margin must be positive, got " << empty_margin);
      prepare ();
      if (empty_margin != empty_views_margin_)
      {
        model_empty_view_ = projectView (model_, model_projections_, empty_margin);
        scene_empty_view_ = projectView (scene_, scene_projections_, empty_margin);
        empty_views_margin_ = empty_margin;
      }
      return violation (t, getFreeSpaceMargin (), *model_empty_view_, *scene_empty_view_);
    }

    double
    CorrespondenceRejectorTensorVerification::violation (const Eigen::Matrix4f& t, double margin, const RangeViewProjection& model_view,
                                                         const RangeViewProjection& scene_view, double stop_above) const
    {
      const double scene = violationFraction (*scene_->fine.cloud, scene_search_, t, model_view, margin, stop_above);
      if (scene > stop_above)
        return scene;
      return std::max (scene, violationFraction (*model_->fine.cloud, model_search_, inverseRigid (t), scene_view, margin, stop_above));
    }

    double
    CorrespondenceRejectorTensorVerification::dimensionExcess (const ViewExtents& model, const ViewExtents& scene,
                                                               const Eigen::Matrix4f& t) const
    {
      return registeredDimensionExcess (model, scene, t.cast<double> (), dims_, params_.checked_dimensions);
    }

    PointToPlaneIcpResult
    CorrespondenceRejectorTensorVerification::icp (const Eigen::Matrix4f& hypothesis, std::size_t min_pairs,
                                                   bool check_stages) const
    {
      const double d_res = getResolution ();
      PointToPlaneIcpParams icp;
      icp.max_iterations = params_.icp_iterations;
      icp.max_distance = params_.icp_max_distance * d_res;
      icp.final_distance = params_.icp_final_distance * d_res;
      icp.min_translation = 1e-3 * d_res;
      icp.coarse_stage_step = params_.icp_coarse_stage_step;
      icp.max_normal_angle = params_.icp_max_normal_angle * M_PI / 180.0;  // pcl::deg2rad (180) exceeds M_PI
      icp.min_pairs = min_pairs;
      if (check_stages)
        icp.continue_after_stage = icp_stage_check_;
      return pointToPlaneIcp (*scene_sample_, *model_->fine.cloud, model_search_, hypothesis, icp);
    }

    Eigen::Matrix4f
    CorrespondenceRejectorTensorVerification::refine (const Eigen::Matrix4f& hypothesis)
    {
      prepare ();
      return icp (hypothesis, icpMinPairs ()).transform;
    }

    bool
    CorrespondenceRejectorTensorVerification::verify (const Eigen::Matrix4f& hypothesis, TensorVerificationResult& result, bool run_icp,
                                                      double dimension_factor)
    {
      if (!(dimension_factor > 0.0) || !std::isfinite (dimension_factor))
        PCL_TENSOR_THROW (BadArgumentException, "verification: the dimension factor must be positive and finite, got " << dimension_factor);
      prepare ();
      const Eigen::Matrix4f start = hypothesis;  // a copy: the caller may pass result.transform itself
      result = TensorVerificationResult ();
      result.transform = start;
      const double d_res = getResolution ();

      // Steps 4-6: the reduced meshes, coarsely registered, must fit the object (Eq. 9, t_D).
      result.coarse_dimension_excess = dimensionExcess (model_reduced_extents_, scene_reduced_extents_, start);
      if (result.coarse_dimension_excess > dimension_factor * params_.coarse_dimension_fraction * dims_.mean ())
      {
        result.stage = TensorVerificationStage::COARSE_DIMENSIONS;
        return false;
      }

      // Steps 7-9: enough correspondences (n_c), estimated on the samples.
      result.required_correspondences = requiredCorrespondences ();
      result.coarse_correspondences = correspondences (*scene_sample_, *model_sample_, start, params_.coarse_distance * d_res);
      if (result.coarse_correspondences < result.required_correspondences)
      {
        result.stage = TensorVerificationStage::COARSE_OVERLAP;
        return false;
      }

      // Step 10: refine with point-to-plane ICP. Fewer pairs than the sampled fine count below needs,
      // even at a coarse stage's wider distance: the hypothesis will fail there, and the finer stages
      // need not run.
      if (run_icp)
      {
        PointToPlaneIcpResult refined = icp (start, icpMinPairs (), true);
        result.transform = refined.transform;
        result.icp_fitness = refined.rms;
        result.icp_stage_transforms = std::move (refined.stage_transforms);
        if (refined.abandoned)
        {
          result.icp_abandoned = true;
          result.stage = TensorVerificationStage::FINE_OVERLAP;
          return false;
        }
      }

      // Steps 11-12: twice n_c correspondences within d_res, over every point; the samples
      // reject clear failures first, since the full count costs a search per point.
      const double sampled = correspondences (*scene_sample_, *model_sample_, result.transform, params_.fine_distance * d_res);
      if (sampled < kSampledFineShare * 2.0 * result.required_correspondences)
      {
        result.fine_correspondences = sampled;
        result.stage = TensorVerificationStage::FINE_OVERLAP;
        return false;
      }
      result.fine_correspondences = correspondences (*scene_->fine.cloud, *model_->fine.cloud, result.transform,
                                                     params_.fine_distance * d_res);
      if (result.fine_correspondences < 2.0 * result.required_correspondences)
      {
        result.stage = TensorVerificationStage::FINE_OVERLAP;
        return false;
      }

      // Steps 13-14: the registered fine meshes must fit the object (Eq. 9), within 2 d_res or a tenth of D.
      result.fine_dimension_excess = dimensionExcess (model_fine_extents_, scene_fine_extents_, result.transform) / d_res;
      if (result.fine_dimension_excess >
          dimension_factor * std::max (params_.fine_dimension_tolerance, params_.fine_dimension_fraction * dims_.mean () / d_res))
      {
        result.stage = TensorVerificationStage::FINE_DIMENSIONS;
        return false;
      }

      // Beyond the paper: neither view may put surface where the other's sensor saw through.
      projectViews ();
      result.free_space_violation = violation (result.transform, getFreeSpaceMargin (), *model_view_, *scene_view_,
                                               kFreeSpaceMeasuredFactor * params_.free_space_fraction);
      if (result.free_space_violation > params_.free_space_fraction)
      {
        result.stage = TensorVerificationStage::FREE_SPACE;
        return false;
      }
      result.stage = TensorVerificationStage::PASSED;
      return true;
    }

    namespace
    {
      /** Of \a from's points (under \a t): the share that \a to's sensor could see, on a line of sight
        * that meets its surface (at any weight but 0: grazing views count, as a common part seen from two
        * sides is grazing in one of them) and not hidden behind it by more than \a margin; the share of
        * those within \a radius of \a to's points; and the share of the points within \a radius that are seen. */
      std::array<double, 3>
      seenAndMatched (const pcl::PointCloud<pcl::PointNormal>& from, const Eigen::Matrix4f& t, const RangeViewProjection& to,
                      const pcl::BoundedNearestSearch& to_search, double margin, double radius)
      {
        std::size_t seen = 0, matched = 0, seen_matched = 0;
        std::int32_t hint = -1;
        RangeViewProjection::Sample sample;
        for (const auto& point : from)
        {
          const Eigen::Vector3f p = (t * point.getVector4fMap ()).head<3> ();
          const bool is_seen = to.sample (p, sample) && sample.weight > 0.0f && sample.distance >= -margin;
          const bool is_matched = to_search.anyWithin (p, static_cast<float> (radius), hint);
          seen += is_seen ? 1 : 0;
          matched += is_matched ? 1 : 0;
          seen_matched += is_seen && is_matched ? 1 : 0;
        }
        const auto share = [] (std::size_t part, std::size_t whole) {
          return whole == 0 ? 0.0 : static_cast<double> (part) / static_cast<double> (whole);
        };
        return {share (seen, from.size ()), share (seen_matched, seen), share (seen_matched, matched)};
      }
    }

    TensorCovisibility
    CorrespondenceRejectorTensorVerification::covisibility (const Eigen::Matrix4f& t)
    {
      prepare ();
      projectViews ();
      const double radius = params_.fine_distance * getResolution (), margin = getFreeSpaceMargin ();
      TensorCovisibility c;
      const auto scene = seenAndMatched (*scene_sample_, t, *model_view_, model_search_, margin, radius);
      const auto model = seenAndMatched (*model_sample_, inverseRigid (t), *scene_view_, scene_search_, margin, radius);
      c.scene_seen = scene[0], c.scene_matched = scene[1], c.scene_matched_seen = scene[2];
      c.model_seen = model[0], c.model_matched = model[1], c.model_matched_seen = model[2];
      return c;
    }

    PoseConditioning
    CorrespondenceRejectorTensorVerification::poseConditioning (const Eigen::Matrix4f& t)
    {
      prepare ();
      // The scene's sample (sample_points) shows the common part's shape as well as every point does.
      const double distance = 2.0 * params_.fine_distance * getResolution ();
      return computePoseConditioning (*scene_sample_, *model_->fine.cloud, model_search_, t, distance);
    }

    void
    CorrespondenceRejectorTensorVerification::getRemainingCorrespondences (const pcl::Correspondences& original,
                                                                          pcl::Correspondences& remaining)
    {
      if (!model_tensors_ || !scene_tensors_)
        PCL_TENSOR_THROW (BadArgumentException, "verification of correspondences needs the model and scene tensors");
      if (!input_matches_.empty () && input_matches_.size () != original.size ())
        PCL_TENSOR_THROW (BadArgumentException, "verification was given " << input_matches_.size () << " match details for "
                          << original.size () << " correspondences");
      pcl::Correspondences kept;
      accepted_transforms_.clear ();
      results_.clear ();
      for (std::size_t i = 0; i < original.size (); ++i)
      {
        if (max_accepted_ > 0 && kept.size () >= max_accepted_)
          break;
        const pcl::Correspondence& c = original[i];
        if (c.index_query < 0 || static_cast<std::size_t> (c.index_query) >= scene_tensors_->size ()
            || c.index_match < 0 || static_cast<std::size_t> (c.index_match) >= model_tensors_->size ())
          PCL_TENSOR_THROW (BadArgumentException, "correspondence " << c.index_query << " -> " << c.index_match
                            << " is outside the tensor clouds");
        TensorMatch match;
        match.model = c.index_match;
        match.scene = c.index_query;
        match.scene_flipped = !input_matches_.empty () && input_matches_[i].scene_flipped;
        TensorVerificationResult result;
        bool passed = verify (transformFromTensorMatch (match, *model_tensors_, *scene_tensors_), result);
        // A bare correspondence does not say which pair order matched: an ambiguous one is tried in both.
        if (!passed && input_matches_.empty () && (*scene_tensors_)[c.index_query].order_ambiguous)
        {
          match.scene_flipped = true;
          passed = verify (transformFromTensorMatch (match, *model_tensors_, *scene_tensors_), result);
        }
        results_.push_back (result);
        if (passed)
        {
          kept.push_back (c);
          accepted_transforms_.push_back (result.transform);
        }
      }
      input_matches_.clear ();
      remaining.swap (kept);
    }
  }
}
