/*
 * pcl_tensor: the options that decide what a pair registration of a multiview run gives, parsed once
 * for every tool that registers such pairs, so that pairs registered apart (pcl_tensor_pairs) equal
 * those pcl_tensor_model registers itself.
 */
#pragma once

#include "tool_main.h"

#include <pcl/registration/multiview_tensor_registration.h>

namespace pcl_tensor_tools
{
  /** --faces N, --dims X,Y,Z and --dims-tolerance T (after ICP, locally, and over all views,
    * globally) into \a params; the other fields keep their values. */
  inline void
  parseMultiviewPairOptions (int argc, char** argv, pcl::registration::MultiviewRegistrationParams& params)
  {
    pcl::console::parse_argument (argc, argv, "--faces", params.pairwise.preparation.target_faces);
    parseObjectDimensions (argc, argv, params.object_dimensions);
    double tolerance = 0.0;
    if (pcl::console::parse_argument (argc, argv, "--dims-tolerance", tolerance) >= 0)
    {
      if (!(tolerance >= 0.0))
        PCL_TENSOR_THROW (pcl::BadArgumentException, "--dims-tolerance must be a non-negative number of d_res");
      params.global_verification.tolerance = tolerance;
      params.pairwise.verification.fine_dimension_tolerance = tolerance;
    }
  }
}
