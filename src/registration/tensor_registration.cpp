/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/tensor_registration.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/time.h>
#include <pcl/common/transforms.h>
#include <pcl/features/tensor.h>

#include <cmath>

namespace pcl
{
  namespace registration
  {
    namespace
    {
      using ViewTensorEstimation = pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor>;

      /** The settings of \a params that TensorEstimation takes; its setters check them. */
      void
      configureEstimation (ViewTensorEstimation& estimation, const TensorRegistrationParams& params)
      {
        estimation.setGridSize (params.grid_size);
        estimation.setPartnersPerVertex (params.partners_per_vertex);
        estimation.setMinNormalAngle (params.min_normal_angle);
        estimation.setRegionGrowing (params.region_growing);
      }
    }

    void
    checkParams (const TensorRegistrationParams& params)
    {
      checkScanPreparationParams (params.preparation);
      ViewTensorEstimation estimation;
      configureEstimation (estimation, params);
      CorrespondenceEstimationTensor matcher;
      configureMatcher (matcher, params);
      CorrespondenceRejectorTensorVerification verifier;
      verifier.setParams (params.verification);
      if (params.max_hypotheses < 0)
        PCL_TENSOR_THROW (BadArgumentException, "the hypothesis cap must be 0 (none) or positive, got " << params.max_hypotheses);
      if (!(params.repeat_rotation >= 0.0 && params.repeat_translation >= 0.0) ||
          !std::isfinite (params.repeat_rotation) || !std::isfinite (params.repeat_translation))
        PCL_TENSOR_THROW (BadArgumentException, "repeat tolerances must be finite and non-negative");
    }

    pcl::PointCloud<pcl::TensorDescriptor>::Ptr
    computeViewTensors (const PreparedScan& scan, const ObjectDimensions& dims, const TensorRegistrationParams& params)
    {
      ViewTensorEstimation estimation;
      estimation.setInputCloud (scan.reduced.cloud);
      estimation.setInputNormals (scan.reduced.cloud);
      estimation.setPolygons (scan.reduced.polygons);
      estimation.setObjectDimensions (dims);
      configureEstimation (estimation, params);
      pcl::PointCloud<pcl::TensorDescriptor>::Ptr tensors (new pcl::PointCloud<pcl::TensorDescriptor>);
      estimation.computeOrThrow (*tensors);
      return tensors;
    }

    namespace
    {
      /** Hypotheses that reached ICP and failed; a close repeat would fail the same way. */
      class RefutedHypotheses
      {
        public:
          RefutedHypotheses (double degrees, double distance) : cos_half_ (std::cos (degrees * M_PI / 360.0)), distance_ (distance) {}

          bool
          contains (const Eigen::Matrix4f& t) const
          {
            for (const auto& r : refuted_)
            {
              const Eigen::Matrix3f d = t.topLeftCorner<3, 3> () * r.topLeftCorner<3, 3> ().transpose ();
              // cos(angle / 2) from the trace of the difference rotation, without acos.
              const double cos_half = 0.5 * std::sqrt (std::max (0.0, 1.0 + static_cast<double> (d.trace ())));
              if (cos_half >= cos_half_ && (t.topRightCorner<3, 1> () - r.topRightCorner<3, 1> ()).norm () <= distance_)
                return true;
            }
            return false;
          }

          void add (const Eigen::Matrix4f& t) { refuted_.push_back (t); }

        private:
          double cos_half_, distance_;
          std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> refuted_;
      };
    }

    void
    configureMatcher (CorrespondenceEstimationTensor& matcher, const TensorRegistrationParams& params)
    {
      matcher.setOverlapThreshold (params.overlap_threshold);
      matcher.setCorrelationThreshold (params.correlation_threshold);
      matcher.setThetaBinWidth (params.theta_bin_width);
      matcher.setOrder (params.order);
    }

    void
    configureVerifier (CorrespondenceRejectorTensorVerification& verifier,
                       const shared_ptr<const PreparedScan>& model, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& model_tensors,
                       const shared_ptr<const PreparedScan>& scene, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& scene_tensors,
                       const ObjectDimensions& dims, const TensorRegistrationParams& params)
    {
      verifier.setModel (model, model_tensors);
      verifier.setScene (scene, scene_tensors);
      verifier.setObjectDimensions (dims);
      verifier.setParams (params.verification);
    }

    Eigen::Matrix4f
    hypothesisOf (const TensorMatch& match, const pcl::PointCloud<pcl::TensorDescriptor>& model_tensors,
                  const pcl::PointCloud<pcl::TensorDescriptor>& scene_tensors)
    {
      const TensorDescriptor& scene = scene_tensors[match.scene];
      return transformFromTensorPair (model_tensors[match.model], match.scene_flipped ? flipPairOrder (scene) : scene);
    }

    void
    registerTensorViews (const shared_ptr<const PreparedScan>& model, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& model_tensors,
                         const shared_ptr<const PreparedScan>& scene, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& scene_tensors,
                         const ObjectDimensions& dims, const TensorRegistrationParams& params, TensorRegistrationReport& report,
                         const HypothesisAcceptor& accept)
    {
      pcl::StopWatch watch;
      report.model_tensors = model_tensors->size ();
      report.scene_tensors = scene_tensors->size ();
      report.registered = false;
      report.transform = Eigen::Matrix4f::Identity ();
      report.failures.fill (0);
      report.hypotheses_tried = 0;
      report.hypotheses_skipped = 0;
      report.hypotheses_refused = 0;
      report.dimensions = dims;
      // A view without tensors (a plane: no two normals theta_d apart) matches nothing: not registered.
      if (model_tensors->empty () || scene_tensors->empty ())
        return;
      CorrespondenceEstimationTensor estimation;
      configureMatcher (estimation, params);
      estimation.setInputSource (scene_tensors);
      estimation.setInputTarget (model_tensors);
      pcl::Correspondences correspondences;
      estimation.determineCorrespondences (correspondences);
      report.matches = correspondences.size ();
      report.comparisons = estimation.getComparisons ();
      report.timings.matching_ms = watch.getTime ();

      watch.reset ();
      CorrespondenceRejectorTensorVerification verification;
      configureVerifier (verification, model, model_tensors, scene, scene_tensors, dims, params);
      report.resolution = verification.getResolution ();
      RefutedHypotheses refuted (params.repeat_rotation, params.repeat_translation * report.resolution);
      const std::vector<TensorMatch>& matches = estimation.getMatches ();
      for (const TensorMatch& match : matches)
      {
        if (params.max_hypotheses > 0 && report.hypotheses_tried >= static_cast<std::size_t> (params.max_hypotheses))
          break;
        const Eigen::Matrix4f hypothesis = hypothesisOf (match, *model_tensors, *scene_tensors);
        if (refuted.contains (hypothesis))
        {
          ++report.hypotheses_skipped;
          continue;
        }
        ++report.hypotheses_tried;
        TensorVerificationResult result;
        const bool verified = verification.verify (hypothesis, result);
        if (verified && accept && !accept (result))
        {
          // Refused by the caller (global verification): a close repeat converges to the same pose.
          ++report.hypotheses_refused;
          refuted.add (hypothesis);
          continue;
        }
        if (verified)
        {
          report.registered = true;
          report.transform = result.transform;
          report.winning_match = match;
          report.verification = result;
          break;
        }
        ++report.failures[static_cast<std::size_t> (result.stage)];
        if (result.stage == TensorVerificationStage::FINE_OVERLAP || result.stage == TensorVerificationStage::FINE_DIMENSIONS)
          refuted.add (hypothesis);
      }
      report.timings.verification_ms = watch.getTime ();
    }

    void
    TensorRegistration::alignOrThrow (PointCloudSource& output)
    {
      if (!input_ || !target_)
        PCL_TENSOR_THROW (BadArgumentException, "TensorRegistration needs a non-empty source (scene) and target (model) cloud");
      for (const auto* cloud : {input_.get (), target_.get ()})
      {
        std::size_t finite = 0;
        for (const auto& p : *cloud)
          finite += pcl::isXYZFinite (p) ? 1 : 0;
        if (finite < 3)
          PCL_TENSOR_THROW (InvalidScanException, "a range image to register has " << finite << " finite points; at least 3 are needed");
      }
      align (output);
    }

    namespace
    {
      /** The centroid of the finite points, in double. */
      Eigen::Vector3d
      finiteCentroid (const pcl::PointCloud<pcl::PointXYZ>& cloud)
      {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
        std::size_t n = 0;
        for (const auto& p : cloud)
          if (pcl::isXYZFinite (p))
          {
            sum += p.getVector3fMap ().cast<double> ();
            ++n;
          }
        return n ? Eigen::Vector3d (sum / static_cast<double> (n)) : sum;
      }

      /** \a cloud moved by -\a centre (organization and NaN cells kept). */
      pcl::PointCloud<pcl::PointXYZ>
      centred (const pcl::PointCloud<pcl::PointXYZ>& cloud, const Eigen::Vector3d& centre)
      {
        pcl::PointCloud<pcl::PointXYZ> out (cloud);
        for (auto& p : out)
          p.getVector3fMap () = (p.getVector3fMap ().cast<double> () - centre).cast<float> ();
        return out;
      }

      ScanViewpoint
      centred (ScanViewpoint viewpoint, const Eigen::Vector3d& centre)
      {
        viewpoint.sensor_pose.translation () -= centre;
        return viewpoint;
      }

      /** A transform between centred views, as one between the views: Tr(model) * t * Tr(-scene). */
      Eigen::Matrix4f
      uncentred (const Eigen::Matrix4f& t, const Eigen::Vector3d& model_centre, const Eigen::Vector3d& scene_centre)
      {
        const Eigen::Affine3d a = Eigen::Translation3d (model_centre) * Eigen::Affine3d (t.cast<double> ()) *
                                  Eigen::Translation3d (-scene_centre);
        return a.matrix ().cast<float> ();
      }
    }

    void
    TensorRegistration::computeTransformation (PointCloudSource& output, const Matrix4& guess)
    {
      (void) guess;  // the method is global: it needs no initial guess
      pcl::StopWatch total, watch;
      report_ = TensorRegistrationReport ();
      // Each view is registered about its own centroid: 1e6 from the origin a float keeps only
      // 1/16 of a unit, and meshing, normals and ICP would work on rounding noise.
      const Eigen::Vector3d model_centre = finiteCentroid (*target_), scene_centre = finiteCentroid (*input_);
      auto model = std::make_shared<PreparedScan> (
          prepareScan (centred (*target_, model_centre), centred (target_viewpoint_, model_centre), params_.preparation));
      auto scene = std::make_shared<PreparedScan> (
          prepareScan (centred (*input_, scene_centre), centred (source_viewpoint_, scene_centre), params_.preparation));
      report_.timings.prepare_ms = watch.getTime ();

      const ObjectDimensions dims = has_dims_ ? dims_
          : computeObjectDimensions<pcl::PointNormal> ({model->fine.cloud.get (), scene->fine.cloud.get ()});
      watch.reset ();
      const auto model_tensors = computeViewTensors (*model, dims, params_);
      const auto scene_tensors = computeViewTensors (*scene, dims, params_);
      report_.timings.tensors_ms = watch.getTime ();

      registerTensorViews (model, model_tensors, scene, scene_tensors, dims, params_, report_);
      if (report_.registered)
      {
        report_.transform = uncentred (report_.transform, model_centre, scene_centre);
        report_.verification.transform = report_.transform;
      }
      converged_ = report_.registered;
      final_transformation_ = report_.transform;
      transformation_ = report_.transform;
      if (converged_)
        pcl::transformPointCloud (*input_, output, final_transformation_);
      report_.timings.total_ms = total.getTime ();
    }
  }
}
