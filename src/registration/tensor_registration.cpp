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
      if (params.scene_tensor_batches < 1 || params.batch_hypotheses < 0)
        PCL_TENSOR_THROW (BadArgumentException, "the scene's tensors need at least one batch and a non-negative number of "
                          "hypotheses per batch, got " << params.scene_tensor_batches << " and " << params.batch_hypotheses);
      if (params.max_hypotheses < 0)
        PCL_TENSOR_THROW (BadArgumentException, "the hypothesis cap must be 0 (none) or positive, got " << params.max_hypotheses);
      if (!(params.repeat_rotation >= 0.0 && params.repeat_translation >= 0.0) ||
          !std::isfinite (params.repeat_rotation) || !std::isfinite (params.repeat_translation))
        PCL_TENSOR_THROW (BadArgumentException, "repeat tolerances must be finite and non-negative");
      if (params.ambiguity_checks < 0 || !(params.ambiguity_rotation >= 0.0 && params.ambiguity_rotation <= 180.0))
        PCL_TENSOR_THROW (BadArgumentException, "ambiguity checks must be non-negative and their rotation in [0, 180] degrees, got "
                          << params.ambiguity_checks << " and " << params.ambiguity_rotation);
    }

    pcl::PointCloud<pcl::TensorDescriptor>::Ptr
    computeViewTensors (const PreparedScan& scan, const ObjectDimensions& dims, const TensorRegistrationParams& params,
                        int batches, int batch)
    {
      ViewTensorEstimation estimation;
      estimation.setPairBatch (batches, batch);
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
      /** cos(angle / 2) of the rotation from \a b to \a a, from the trace, without acos. */
      double
      cosHalfAngleBetween (const Eigen::Matrix4f& a, const Eigen::Matrix4f& b)
      {
        const Eigen::Matrix3f d = a.topLeftCorner<3, 3> () * b.topLeftCorner<3, 3> ().transpose ();
        return 0.5 * std::sqrt (std::max (0.0, 1.0 + static_cast<double> (d.trace ())));
      }

      /** Two poses within \a degrees of each other that put \a point within \a distance of the same place. */
      bool
      posesAgree (const Eigen::Matrix4f& a, const Eigen::Matrix4f& b, const Eigen::Vector4f& point, double degrees, double distance)
      {
        return cosHalfAngleBetween (a, b) >= std::cos (degrees * M_PI / 360.0) &&
               static_cast<double> (((a - b) * point).norm ()) <= distance;
      }

      /** Hypotheses that reached ICP and failed; a close repeat would fail the same way. */
      class RefutedHypotheses
      {
        public:
          RefutedHypotheses (double degrees, double distance) : cos_half_ (std::cos (degrees * M_PI / 360.0)), distance_ (distance) {}

          bool
          contains (const Eigen::Matrix4f& t) const
          {
            for (const auto& r : refuted_)
              if (cosHalfAngleBetween (t, r) >= cos_half_ && (t.topRightCorner<3, 1> () - r.topRightCorner<3, 1> ()).norm () <= distance_)
                return true;
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

    namespace
    {
      /** The report of a registration about to start: nothing tried, nothing found. */
      void
      resetReport (TensorRegistrationReport& report, std::size_t model_tensors, const ObjectDimensions& dims)
      {
        report.model_tensors = model_tensors;
        report.scene_tensors = 0;
        report.matches = 0;
        report.comparisons = 0;
        report.registered = false;
        report.transform = Eigen::Matrix4f::Identity ();
        report.failures.fill (0);
        report.hypotheses_tried = 0;
        report.hypotheses_skipped = 0;
        report.hypotheses_refused = 0;
        report.ambiguity_checks = 0;
        report.ambiguous = false;
        report.rival_transform = Eigen::Matrix4f::Identity ();
        report.dimensions = dims;
        report.timings.matching_ms = 0.0;
        report.timings.verification_ms = 0.0;
      }

      /** Matching and verification of one view pair, batch after batch of scene tensors: the refuted
        * hypotheses, the hypothesis count and the verifier's search structures carry over. */
      class HypothesisSearch
      {
        public:
          HypothesisSearch (const shared_ptr<const PreparedScan>& model, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& model_tensors,
                            const shared_ptr<const PreparedScan>& scene, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& scene_tensors,
                            const ObjectDimensions& dims, const TensorRegistrationParams& params, TensorRegistrationReport& report,
                            const HypothesisAcceptor& accept)
            : model_tensors_ (model_tensors), params_ (params), report_ (report), accept_ (accept),
              scene_centroid_ (centroidOf (*scene->fine.cloud)),
              far_distance_ (0.5 * dims.mean ())
          {
            configureVerifier (verification_, model, model_tensors, scene, scene_tensors, dims, params);
            report.resolution = verification_.getResolution ();
            refuted_ = RefutedHypotheses (params.repeat_rotation, params.repeat_translation * report.resolution);
          }

          /** Match \a batch (scene tensors from index \a first on) and verify its first \a budget
            * matches in order (0: all); the others wait for finish().
            * \return true once registered or out of hypotheses: no later batch is needed */
          bool
          search (const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& batch, std::size_t first, std::size_t budget = 0)
          {
            pcl::StopWatch watch;
            CorrespondenceEstimationTensor estimation;
            configureMatcher (estimation, params_);
            estimation.setInputSource (batch);
            estimation.setInputTarget (model_tensors_);
            pcl::Correspondences correspondences;
            estimation.determineCorrespondences (correspondences);
            report_.matches += correspondences.size ();
            report_.comparisons += estimation.getComparisons ();
            report_.timings.matching_ms += watch.getTime ();
            watch.reset ();
            const std::vector<TensorMatch> matches = estimation.getMatches ();
            const std::size_t now = budget > 0 ? std::min (budget, matches.size ()) : matches.size ();
            // The deferred matches may still serve as rivals of a pose this batch verifies.
            const bool done = verify (matches, now, *batch, first);
            if (!done)
              for (auto m = matches.begin () + static_cast<std::ptrdiff_t> (now); m != matches.end (); ++m)
              {
                deferred_.push_back (*m);
                deferred_.back ().scene += static_cast<int> (first);
              }
            report_.timings.verification_ms += watch.getTime ();
            return done;
          }

          /** Verify the matches search() deferred, all batches' together in the matcher's order, on
            * \a scene_tensors, every batch's tensors in the order they were computed. */
          void
          finish (const pcl::PointCloud<pcl::TensorDescriptor>& scene_tensors)
          {
            pcl::StopWatch watch;
            sortTensorMatches (deferred_, params_.order);
            verify (deferred_, deferred_.size (), scene_tensors, 0);
            deferred_.clear ();
            report_.timings.verification_ms += watch.getTime ();
          }

        private:
          bool
          capReached () const
          {
            return params_.max_hypotheses > 0 && report_.hypotheses_tried >= static_cast<std::size_t> (params_.max_hypotheses);
          }

          static Eigen::Vector4f
          centroidOf (const pcl::PointCloud<pcl::PointNormal>& cloud)
          {
            Eigen::Vector4d sum = Eigen::Vector4d::Zero ();
            for (const auto& p : cloud)
              sum.head<3> () += p.getVector3fMap ().cast<double> ();
            sum /= static_cast<double> (std::max<std::size_t> (1, cloud.size ()));
            sum.w () = 1.0;
            return sum.cast<float> ();
          }

          /** Local verification, then the caller's acceptor; refuted poses are remembered. */
          bool
          passes (const Eigen::Matrix4f& hypothesis, TensorVerificationResult& result)
          {
            if (!verification_.verify (hypothesis, result))
            {
              if (result.stage == TensorVerificationStage::FINE_OVERLAP || result.stage == TensorVerificationStage::FINE_DIMENSIONS)
                refuted_.add (hypothesis);
              return false;
            }
            if (accept_ && !accept_ (result))
            {
              // Refused by the caller (global verification): a close repeat converges to the same pose.
              ++report_.hypotheses_refused;
              refuted_.add (hypothesis);
              return false;
            }
            return true;
          }

          /** A second pose, other than \a pose, that the matches after \a from also verify; the matches
            * whose hypothesis is near \a pose are taken as leading to it and skipped. */
          bool
          findRival (const std::vector<TensorMatch>& matches, std::size_t from, const pcl::PointCloud<pcl::TensorDescriptor>& batch,
                     const Eigen::Matrix4f& pose)
          {
            int checks = 0;
            for (std::size_t k = from; k < matches.size () && checks < params_.ambiguity_checks; ++k)
            {
              const Eigen::Matrix4f hypothesis = hypothesisOf (matches[k], *model_tensors_, batch);
              if (posesAgree (hypothesis, pose, scene_centroid_, params_.ambiguity_rotation, far_distance_) || refuted_.contains (hypothesis))
                continue;
              ++checks;
              ++report_.ambiguity_checks;
              TensorVerificationResult result;
              if (passes (hypothesis, result) && !posesAgree (result.transform, pose, scene_centroid_, params_.repeat_rotation,
                                                              params_.repeat_translation * report_.resolution))
              {
                report_.rival_transform = result.transform;
                return true;
              }
            }
            return false;
          }

          /** Verify the first \a count of \a matches in order; all of them may serve as rivals. */
          bool
          verify (const std::vector<TensorMatch>& matches, std::size_t count, const pcl::PointCloud<pcl::TensorDescriptor>& batch,
                  std::size_t first)
          {
            for (std::size_t k = 0; k < count; ++k)
            {
              if (capReached ())
                return true;
              const TensorMatch& match = matches[k];
              const Eigen::Matrix4f hypothesis = hypothesisOf (match, *model_tensors_, batch);
              if (refuted_.contains (hypothesis))
              {
                ++report_.hypotheses_skipped;
                continue;
              }
              ++report_.hypotheses_tried;
              TensorVerificationResult result;
              if (!passes (hypothesis, result))
              {
                if (result.stage != TensorVerificationStage::PASSED)
                  ++report_.failures[static_cast<std::size_t> (result.stage)];
                continue;
              }
              // Two poses that both verify: no evidence picks one, so neither is reported.
              report_.ambiguous = findRival (matches, k + 1, batch, result.transform);
              report_.registered = !report_.ambiguous;
              report_.winning_match = match;
              report_.winning_match.scene += static_cast<decltype (match.scene)> (first);
              report_.verification = result;
              if (report_.registered)
                report_.transform = result.transform;
              return true;
            }
            return capReached ();
          }

          pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr model_tensors_;
          const TensorRegistrationParams& params_;
          TensorRegistrationReport& report_;
          const HypothesisAcceptor& accept_;
          CorrespondenceRejectorTensorVerification verification_;
          RefutedHypotheses refuted_{0.0, 0.0};
          Eigen::Vector4f scene_centroid_;  ///< where poses are compared (homogeneous)
          double far_distance_;             ///< mean(D) / 2: a pose moving the centroid farther is another pose
          std::vector<TensorMatch> deferred_;  ///< scene indices into all batches' tensors
      };
    }

    void
    registerTensorViews (const shared_ptr<const PreparedScan>& model, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& model_tensors,
                         const shared_ptr<const PreparedScan>& scene, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& scene_tensors,
                         const ObjectDimensions& dims, const TensorRegistrationParams& params, TensorRegistrationReport& report,
                         const HypothesisAcceptor& accept)
    {
      resetReport (report, model_tensors->size (), dims);
      report.scene_tensors = scene_tensors->size ();
      // A view without tensors (a plane: no two normals theta_d apart) matches nothing: not registered.
      if (model_tensors->empty () || scene_tensors->empty ())
        return;
      HypothesisSearch (model, model_tensors, scene, scene_tensors, dims, params, report, accept).search (scene_tensors, 0);
    }

    void
    registerTensorViewsInBatches (const shared_ptr<const PreparedScan>& model, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& model_tensors,
                                  const shared_ptr<const PreparedScan>& scene, const ObjectDimensions& dims,
                                  const TensorRegistrationParams& params, TensorRegistrationReport& report,
                                  const HypothesisAcceptor& accept)
    {
      resetReport (report, model_tensors->size (), dims);
      if (model_tensors->empty ())
        return;
      // Every batch joins the scene's tensors, so that the winning match's index refers to them all.
      pcl::PointCloud<pcl::TensorDescriptor>::Ptr scene_tensors (new pcl::PointCloud<pcl::TensorDescriptor>);
      HypothesisSearch hypotheses (model, model_tensors, scene, scene_tensors, dims, params, report, accept);
      const auto budget = static_cast<std::size_t> (params.batch_hypotheses);
      for (int batch = 0; batch < params.scene_tensor_batches; ++batch)
      {
        pcl::StopWatch watch;
        const auto tensors = computeViewTensors (*scene, dims, params, params.scene_tensor_batches, batch);
        report.timings.tensors_ms += watch.getTime ();
        const std::size_t first = scene_tensors->size ();
        *scene_tensors += *tensors;
        report.scene_tensors = scene_tensors->size ();
        if (!tensors->empty () && hypotheses.search (tensors, first, budget))
          return;
      }
      hypotheses.finish (*scene_tensors);
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
      report_.timings.tensors_ms = watch.getTime ();
      // The scene's tensors batch by batch, as the hypotheses need them (Fig. 7).
      registerTensorViewsInBatches (model, model_tensors, scene, dims, params_, report_);
      if (report_.registered || report_.ambiguous)
        report_.verification.transform = uncentred (report_.verification.transform, model_centre, scene_centre);
      if (report_.registered)
        report_.transform = report_.verification.transform;
      if (report_.ambiguous)
        report_.rival_transform = uncentred (report_.rival_transform, model_centre, scene_centre);
      converged_ = report_.registered;
      final_transformation_ = report_.transform;
      transformation_ = report_.transform;
      if (converged_)
        pcl::transformPointCloud (*input_, output, final_transformation_);
      report_.timings.total_ms = total.getTime ();
    }
  }
}
