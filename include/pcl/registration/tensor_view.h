/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/common/scan_viewpoint.h>
#include <pcl/features/tensor_descriptor.h>
#include <pcl/registration/tensor_registration_params.h>
#include <pcl/surface/range_view_projection_memo.h>
#include <pcl/surface/scan_preparation.h>

#include <memory>

namespace pcl
{
  namespace registration
  {
    /** \brief One range image ready to register: its meshes M_i and M'_i with normals (Section 2) and,
      * once computed, its tensors. TensorRegistration takes views it already has, as
      * pcl::SampleConsensusPrerejective takes features, so that a view is prepared once however many
      * pairs it is registered in (MultiviewTensorRegistration, the bench).
      *
      * The meshes lie in the view's frame moved by -origin: prepareTensorView() centres each scan on
      * its centroid, since 1e6 from the origin a float keeps only 1/16 of a unit and meshing, normals
      * and ICP would work on rounding noise (doc/design.md#two-raw-scans-in-tensorregistration).
      * \ingroup registration
      */
    struct TensorView
    {
      using Ptr = shared_ptr<TensorView>;
      using ConstPtr = shared_ptr<const TensorView>;

      /** M_i and M'_i, in the view's frame less origin. Never null in a usable view. */
      shared_ptr<const PreparedScan> scan;
      /** The tensors of M'_i, computed with D = dimensions (Eq. 2-3); null: not computed yet, and a
        * registration computes them as it needs them, in batches (the scene of Fig. 7). */
      pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr tensors;
      /** D the tensors were computed with. */
      ObjectDimensions dimensions;
      /** Where the meshes' origin lies in the view's own frame. */
      Eigen::Vector3d origin = Eigen::Vector3d::Zero ();
      /** The z-buffers of \a scan that verification has built, kept for the view's other pairs (copies
        * of the view share them; null: each pair builds its own). */
      RangeViewProjectionMemo::Ptr projections = std::make_shared<RangeViewProjectionMemo> ();
    };

    /** \brief The centroid of the finite points of \a cloud, in double (zero when there are none). */
    Eigen::Vector3d
    finiteCentroid (const pcl::PointCloud<pcl::PointXYZ>& cloud);

    /** \brief Mesh and reduce one range image (prepareScan()), centred on its finite centroid, into a
      * view without tensors.
      * \param[in] cloud the range image (organized or not; NaN allowed)
      * \param[in] viewpoint its sensor, in the frame of \a cloud
      * \param[in] params the preparation settings (TensorRegistrationParams::preparation)
      * \throw pcl::InvalidScanException on unusable data, pcl::BadArgumentException on bad parameters
      */
    TensorView::Ptr
    prepareTensorView (const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                       const ScanPreparationParams& params);

    /** \brief The tensors of one prepared view (Section 2), with Eq. 2 and Eq. 3 taken from \a dims.
      * (To compute them in batches, keep one TensorEstimation and call setPairBatch: it forms the pairs once.)
      * \throw pcl::BadArgumentException or pcl::InvalidScanException on unusable input
      */
    pcl::PointCloud<pcl::TensorDescriptor>::Ptr
    computeViewTensors (const PreparedScan& scan, const ObjectDimensions& dims, const TensorRegistrationParams& params);

    /** \brief \a view with its tensors computed with \a dims (a copy: the meshes are shared). */
    TensorView::Ptr
    withTensors (const TensorView& view, const ObjectDimensions& dims, const TensorRegistrationParams& params);

    /** \brief A transform between two views' centred meshes as one between the views' own frames:
      * Tr(model.origin) * t * Tr(-scene.origin). */
    Eigen::Matrix4f
    betweenViewFrames (const Eigen::Matrix4f& t, const TensorView& model, const TensorView& scene);

    /** \brief The inverse of betweenViewFrames(): a transform between the views' frames as one between
      * their centred meshes. */
    Eigen::Matrix4f
    betweenCentredMeshes (const Eigen::Matrix4f& t, const TensorView& model, const TensorView& scene);
  }
}
