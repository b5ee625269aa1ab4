/*
 * pcl_tensor evaluation: discriminating power of tensors against spin images (Section 8, Fig. 21).
 */
#pragma once

#include "eval_views.h"
#include "spin_image_baseline.h"

#include <vector>

namespace pcl_tensor_eval
{
  /** \brief Section 8's set-up: equal bin sizes (the reduced mesh's resolution), 700 descriptors per view,
    * the best 200 matches by correlation.
    */
  struct DiscriminationParams
  {
    int tensor_grid = 15;      ///< the paper's 15 x 15 x 15 tensors
    int descriptors = 700;     ///< per view, drawn at random (seed) from every vertex or pair
    int best_matches = 200;
    std::uint32_t seed = 2006;
  };

  /** \brief Ground-truth displacement of the best matches of one pair, in bins (= the reduced mesh's d_res). */
  struct DiscriminationErrors
  {
    std::vector<double> tensor_bins, spin_bins;
  };

  /** \brief Compute both descriptors on the two views' reduced meshes, match each, and measure how
    * far apart the best matches' points are once the ground truth aligns the views (tensors: the frame
    * origins; spin images: the vertices).
    */
  DiscriminationErrors
  measureDiscrimination (const EvalView& model, const EvalView& scene, const pcl::ObjectDimensions& dims,
                         const pcl::registration::TensorRegistrationParams& tensor_params, const DiscriminationParams& params);
}
