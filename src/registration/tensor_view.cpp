/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/tensor_view.h>
#include <pcl/common/point_tests.h>

namespace pcl
{
  namespace registration
  {
    namespace
    {
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
    }

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

    TensorView::Ptr
    prepareTensorView (const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                       const ScanPreparationParams& params)
    {
      auto view = std::make_shared<TensorView> ();
      view->origin = finiteCentroid (cloud);
      view->scan = std::make_shared<const PreparedScan> (
          prepareScan (centred (cloud, view->origin), centred (viewpoint, view->origin), params));
      return view;
    }

    TensorView::Ptr
    withTensors (const TensorView& view, const ObjectDimensions& dims, const TensorRegistrationParams& params)
    {
      auto out = std::make_shared<TensorView> (view);
      out->tensors = computeViewTensors (*view.scan, dims, params);
      out->dimensions = dims;
      return out;
    }

    Eigen::Matrix4f
    betweenViewFrames (const Eigen::Matrix4f& t, const TensorView& model, const TensorView& scene)
    {
      const Eigen::Affine3d a = Eigen::Translation3d (model.origin) * Eigen::Affine3d (t.cast<double> ()) *
                                Eigen::Translation3d (-scene.origin);
      return a.matrix ().cast<float> ();
    }

    Eigen::Matrix4f
    betweenCentredMeshes (const Eigen::Matrix4f& t, const TensorView& model, const TensorView& scene)
    {
      const Eigen::Affine3d a = Eigen::Translation3d (-model.origin) * Eigen::Affine3d (t.cast<double> ()) *
                                Eigen::Translation3d (scene.origin);
      return a.matrix ().cast<float> ();
    }
  }
}
