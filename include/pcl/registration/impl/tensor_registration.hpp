/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/registration/tensor_registration.h>
#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/transforms.h>

#include <type_traits>

namespace pcl
{
  namespace registration
  {
    namespace detail
    {
      /** \a cloud as XYZ points: itself for pcl::PointXYZ, a copy of the coordinates otherwise. */
      template <typename PointT> pcl::PointCloud<pcl::PointXYZ>::ConstPtr
      xyzOf (const typename pcl::PointCloud<PointT>::ConstPtr& cloud)
      {
        if constexpr (std::is_same_v<PointT, pcl::PointXYZ>)
          return cloud;
        else
        {
          pcl::PointCloud<pcl::PointXYZ>::Ptr xyz (new pcl::PointCloud<pcl::PointXYZ>);
          pcl::copyPointCloud (*cloud, *xyz);
          return xyz;
        }
      }

      template <typename PointT> std::size_t
      finitePointCount (const pcl::PointCloud<PointT>& cloud)
      {
        std::size_t finite = 0;
        for (const auto& p : cloud)
          finite += pcl::isXYZFinite (p) ? 1 : 0;
        return finite;
      }
    }

    template <typename PointSource, typename PointTarget> void
    TensorRegistration<PointSource, PointTarget>::alignOrThrow (PointCloudSource& output, const Matrix4& guess)
    {
      if (!this->input_ || !this->target_)
        PCL_TENSOR_THROW (BadArgumentException, "TensorRegistration needs a non-empty source (scene) and target (model) cloud");
      const std::size_t finite[] = {detail::finitePointCount (*this->input_), detail::finitePointCount (*this->target_)};
      for (const std::size_t n : finite)
        if (n < 3)
          PCL_TENSOR_THROW (InvalidScanException, "a range image to register has " << n << " finite points; at least 3 are needed");
      this->align (output, guess);
    }

    template <typename PointSource, typename PointTarget> void
    TensorRegistration<PointSource, PointTarget>::computeTransformation (PointCloudSource& output, const Matrix4& guess)
    {
      detail::RegistrationSide model, scene;
      model.view = target_view_;
      model.viewpoint = target_viewpoint_;
      if (!target_view_)
        model.cloud = detail::xyzOf<PointTarget> (this->target_);
      scene.view = source_view_;
      scene.viewpoint = source_viewpoint_;
      if (!source_view_)
        scene.cloud = detail::xyzOf<PointSource> (this->input_);
      const Eigen::Matrix4f g = guess;
      report_ = detail::registerViewPair (model, scene, has_dims_ ? &dims_ : nullptr, params_, accept_,
                                          verify_guess_ ? &g : nullptr, threads_);
      this->converged_ = report_.registered;
      this->final_transformation_ = report_.transform;
      this->transformation_ = report_.transform;
      if (this->converged_)
        pcl::transformPointCloud (*this->input_, output, this->final_transformation_);
    }

    template <typename PointSource, typename PointTarget> double
    TensorRegistration<PointSource, PointTarget>::getFitnessScore (double max_range)
    {
      if (!this->input_ || !this->target_)
        return std::numeric_limits<double>::max ();
      if (!fitness_tree_)
      {
        auto finite = std::make_shared<pcl::Indices> ();
        for (std::size_t i = 0; i < this->target_->size (); ++i)
          if (pcl::isXYZFinite ((*this->target_)[i]))
            finite->push_back (static_cast<pcl::index_t> (i));
        fitness_tree_.reset (new pcl::KdTreeFLANN<PointTarget>);
        if (finite->empty ())
          return std::numeric_limits<double>::max ();
        fitness_tree_->setInputCloud (this->target_, finite);
      }
      if (!fitness_tree_->getInputCloud ())
        return std::numeric_limits<double>::max ();
      pcl::Indices nn_index (1);
      std::vector<float> nn_distance (1);
      double sum = 0.0;
      std::size_t pairs = 0;
      for (const auto& p : *this->input_)
      {
        if (!pcl::isXYZFinite (p))
          continue;
        PointTarget q;
        q.getVector4fMap () = this->final_transformation_ * Eigen::Vector4f (p.x, p.y, p.z, 1.0f);
        fitness_tree_->nearestKSearch (q, 1, nn_index, nn_distance);
        if (nn_distance[0] <= max_range)
        {
          sum += nn_distance[0];
          ++pairs;
        }
      }
      return pairs > 0 ? sum / static_cast<double> (pairs) : std::numeric_limits<double>::max ();
    }
  }
}

#define PCL_INSTANTIATE_TensorRegistration(Source, Target) \
  template class PCL_EXPORTS pcl::registration::TensorRegistration<Source, Target>;
