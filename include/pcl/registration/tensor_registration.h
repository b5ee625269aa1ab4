/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/common/scan_viewpoint.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/registration/registration.h>
#include <pcl/registration/tensor_registration_params.h>
#include <pcl/registration/tensor_registration_report.h>
#include <pcl/registration/tensor_view.h>

#include <limits>

namespace pcl
{
  namespace registration
  {
    namespace detail
    {
      /** \brief One side of a pair: a view already prepared, or the cloud to prepare and its sensor. */
      struct RegistrationSide
      {
        TensorView::ConstPtr view;
        pcl::PointCloud<pcl::PointXYZ>::ConstPtr cloud;
        ScanViewpoint viewpoint = ScanViewpoint::fromPositiveZ ();
      };

      /** \brief The work of TensorRegistration::align(), on XYZ points (TensorRegistration's template
        * parameters only choose the clouds it is given): each side prepared unless given as a view, D
        * from the pair unless \a dims, the search, and the transform between the views' own frames.
        */
      TensorRegistrationReport
      registerViewPair (const RegistrationSide& model, const RegistrationSide& scene, const ObjectDimensions* dims,
                        const TensorRegistrationParams& params, const HypothesisAcceptor& accept, const Eigen::Matrix4f* guess,
                        unsigned threads);
    }

    /** \brief Automatic pairwise registration of range images with tensors (Mian, Bennamoun & Owens,
      * IJCV 2006), used like pcl::SampleConsensusPrerejective: set the scene as source and the model as
      * target, call align(). It meshes and reduces both range images (or takes TensorView objects
      * prepared before, setSourceView()/setTargetView()), computes their tensors (pcl::TensorEstimation),
      * matches them (CorrespondenceEstimationTensor) and verifies one hypothesis at a time through
      * CorrespondenceRejectorTensorVerification::getRemainingCorrespondences() until one passes local
      * verification (Section 4.1) and the hypothesis acceptor, if set. hasConverged() is false when
      * none does, or when two distinct poses do (an ambiguous pair): the views are then reported as
      * not registered, never with an unverified transform.
      *
      * The method is global: align(output, guess) ignores \a guess unless setVerifyGuess(true), in which
      * case the guess is verified first, like any hypothesis, and taken if it passes.
      *
      * Inherited settings it does not use, since the tensor pipeline has its own (TensorRegistrationParams):
      * setMaximumIterations, setTransformationEpsilon, setTransformationRotationEpsilon,
      * setEuclideanFitnessEpsilon, setMaxCorrespondenceDistance, setRANSACOutlierRejectionThreshold,
      * setRANSACIterations, setTransformationEstimation, setCorrespondenceEstimation,
      * addCorrespondenceRejector, setSearchMethodTarget and setSearchMethodSource.
      * getFitnessScore() is this class's own: it skips NaN points, which pcl::Registration's aborts on.
      * \tparam PointSource, PointTarget any point type with x, y, z (instantiated for pcl::PointXYZ,
      *         pcl::PointNormal and pcl::PointXYZRGB); only the coordinates are used
      * \ingroup registration
      */
    /** \brief Register two prepared views with D = \a dims, as TensorRegistration::align() does with
      * the views it is given, without clouds: the report's transform takes \a scene's own frame into
      * \a model's. Tensors a view lacks are computed with \a dims. For many views of one object,
      * prepared once (MultiviewTensorRegistration, pcl_tensor_pairs).
      * \throw pcl::BadArgumentException on bad parameters or a null view
      */
    TensorRegistrationReport
    registerTensorViews (const TensorView::ConstPtr& model, const TensorView::ConstPtr& scene, const ObjectDimensions& dims,
                         const TensorRegistrationParams& params, const HypothesisAcceptor& accept = {});

    template <typename PointSource = pcl::PointXYZ, typename PointTarget = PointSource>
    class TensorRegistration : public Registration<PointSource, PointTarget, float>
    {
      public:
        using Ptr = shared_ptr<TensorRegistration<PointSource, PointTarget>>;
        using ConstPtr = shared_ptr<const TensorRegistration<PointSource, PointTarget>>;
        using Base = Registration<PointSource, PointTarget, float>;
        using typename Base::PointCloudSource;
        using typename Base::PointCloudTargetConstPtr;
        using typename Base::Matrix4;
        using Base::getFitnessScore;

        TensorRegistration ()
        {
          this->reg_name_ = "TensorRegistration";
          // The method searches structures of its own: the base class's kd-tree of the target would
          // cost time on every align() and serve nothing.
          this->force_no_recompute_ = true;
        }

        /** \brief Set every parameter at once.
          * \throw pcl::BadArgumentException when one is out of range (see checkParams()) */
        void setParams (const TensorRegistrationParams& params)
        {
          checkParams (params);
          params_ = params;
        }
        const TensorRegistrationParams& getParams () const { return params_; }

        /** \brief Sensors of the scene (source) and model (target); default: +z (ScanViewpoint::fromPositiveZ). */
        void setSourceViewpoint (const ScanViewpoint& v) { source_viewpoint_ = v; }
        void setTargetViewpoint (const ScanViewpoint& v) { target_viewpoint_ = v; }

        /** \brief Views prepared before (prepareTensorView()), used instead of preparing the source and
          * target clouds, which then serve only for align()'s output and getFitnessScore(): they must be
          * the views' clouds. A view's tensors, when it has them, must have been computed with the D
          * this registration uses (setObjectDimensions()). Null (default): prepare the cloud. */
        void setSourceView (const TensorView::ConstPtr& view) { source_view_ = view; }
        void setTargetView (const TensorView::ConstPtr& view) { target_view_ = view; }
        const TensorView::ConstPtr& getSourceView () const { return source_view_; }
        const TensorView::ConstPtr& getTargetView () const { return target_view_; }

        /** \brief The object's dimensions D, from all its views (Eq. 1). Without it, D comes from the
          * two views alone, which underestimates the object when the views cover little of it.
          */
        void setObjectDimensions (const ObjectDimensions& dims) { dims_ = dims; has_dims_ = true; }

        /** \brief A further test of every locally verified hypothesis, e.g. global verification
          * (Section 4.2); empty (default): none. */
        void setHypothesisAcceptor (const HypothesisAcceptor& accept) { accept_ = accept; }

        /** \brief Verify align()'s guess before any tensor match, and take it when it passes (default
          * false: the guess is ignored, as the method needs none). */
        void setVerifyGuess (bool verify) { verify_guess_ = verify; }
        bool getVerifyGuess () const { return verify_guess_; }

        /** \brief Threads for preparing the two clouds at once (0: every core; default 1, since a
          * caller that runs many registrations in parallel has its cores busy already). The result is
          * the same for any number. */
        void setNumberOfThreads (unsigned threads) { threads_ = threads; }
        unsigned getNumberOfThreads () const { return threads_; }

        /** \brief align(), but unusable input throws instead of being logged by PCL's Registration:
          * pcl::BadArgumentException when a cloud is missing, pcl::InvalidScanException when one has
          * fewer than three finite points. Either way no transform is reported.
          */
        void alignOrThrow (PointCloudSource& output, const Matrix4& guess = Matrix4::Identity ());

        /** \brief What the last align() did. */
        const TensorRegistrationReport& getReport () const { return report_; }

        /** \brief The mean squared distance from the finite source points, moved by the final
          * transformation, to their nearest finite target points, over the pairs whose squared
          * distance is at most \a max_range (as pcl::Registration compares it); the largest double
          * when there is none.
          */
        double getFitnessScore (double max_range = std::numeric_limits<double>::max ());

        void setInputTarget (const PointCloudTargetConstPtr& cloud) override
        {
          Base::setInputTarget (cloud);
          fitness_tree_.reset ();
        }

      protected:
        void computeTransformation (PointCloudSource& output, const Matrix4& guess) override;

      private:
        TensorRegistrationParams params_;
        ScanViewpoint source_viewpoint_ = ScanViewpoint::fromPositiveZ ();
        ScanViewpoint target_viewpoint_ = ScanViewpoint::fromPositiveZ ();
        TensorView::ConstPtr source_view_, target_view_;
        ObjectDimensions dims_;
        bool has_dims_{false};
        HypothesisAcceptor accept_;
        bool verify_guess_{false};
        unsigned threads_{1};
        TensorRegistrationReport report_;
        /** The finite target points, searched by getFitnessScore(); built when first needed. */
        shared_ptr<pcl::KdTreeFLANN<PointTarget>> fitness_tree_;
    };
  }
}

#ifdef PCL_NO_PRECOMPILE
#include <pcl/registration/impl/tensor_registration.hpp>
#endif
