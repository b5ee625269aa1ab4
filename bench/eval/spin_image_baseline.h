/*
 * pcl_tensor evaluation: the spin-image comparison of Section 8 (Fig. 20), with pcl::SpinImageEstimation
 * on the same reduced meshes and the same local verification as the tensor method.
 */
#pragma once

#include "eval_views.h"

#include <pcl/point_types.h>

namespace pcl_tensor_eval
{
  /** \brief PCL 1.13.0's spin images work only at image width 8, i.e. pcl::Histogram<153> = 9 x 17
    * bins (PCL issue #5039); the paper's 15 x 15 cannot be computed with it.
    */
  constexpr int kSpinImageWidth = 8;
  using SpinImage = pcl::Histogram<153>;

  /** \brief How spin images are computed and matched. */
  struct SpinImageParams
  {
    /** Bin size in units of the tensor's bin size b_s = mean(D)/30 (Eq. 3): the paper matched the two
      * descriptors' bin sizes (Section 8). The support radius is kSpinImageWidth bins. */
    double bin_size_tensor_bins = 1.0;
    /** Support angle (Johnson and Hebert: 60 deg): surface points whose normal turns further away are left out. */
    double support_angle_deg = 60.0;
    /** Correspondences (each scene image's best model image) considered for grouping, best correlation first. */
    int candidates = 200;
    /** Two correspondences are geometrically consistent when their distances agree within this fraction
      * of the distance (and a few d_res of the reduced mesh) and their normals' angles within this many degrees. */
    double consistency_fraction = 0.1;
    double consistency_angle_deg = 10.0;
    /** Hypotheses (one group per seed correspondence) verified at most: the tensor method's cap. */
    int max_hypotheses = 300;
  };

  /** \brief The spin images of one view's reduced mesh M'_i, one per vertex with a finite normal. */
  struct SpinImageView
  {
    pcl::PointCloud<pcl::PointNormal>::Ptr points{new pcl::PointCloud<pcl::PointNormal>};
    pcl::PointCloud<SpinImage>::Ptr images{new pcl::PointCloud<SpinImage>};
  };

  /** \brief Spin images of every vertex of \a mesh, with the mesh's vertices as the support surface.
    * \param[in] bin_size the spin image's bin size (its support radius is kSpinImageWidth bins)
    */
  SpinImageView
  computeSpinImages (const pcl::ScanMesh& mesh, double bin_size, const SpinImageParams& params);

  /** \brief Pearson's correlation coefficient of two spin images (the matching criterion of Section 8). */
  double
  spinImageCorrelation (const SpinImage& a, const SpinImage& b);

  /** \brief One correspondence: scene image -> its best model image. */
  struct SpinImageMatch
  {
    int scene = -1, model = -1;
    double correlation = 0.0;
  };

  /** \brief Each scene image's best model image, highest correlation first. */
  std::vector<SpinImageMatch>
  matchSpinImages (const SpinImageView& model, const SpinImageView& scene);

  /** \brief What spin-image registration did on one pair. */
  struct SpinImageResult
  {
    bool registered = false;
    Eigen::Matrix4f transform = Eigen::Matrix4f::Identity ();
    std::size_t hypotheses = 0;
  };

  /** \brief Register the scene view to the model view as Johnson and Hebert do (match, group
    * geometrically consistent correspondences around each seed, one rigid transform per group), and
    * verify each group's transform with the tensor method's local verification until one passes.
    */
  SpinImageResult
  registerSpinImages (const EvalView& model, const SpinImageView& model_images, const EvalView& scene,
                      const SpinImageView& scene_images, const pcl::ObjectDimensions& dims,
                      const pcl::registration::TensorRegistrationParams& tensor_params, const SpinImageParams& params);
}
