/*
 * pcl_tensor: the options that decide what a pair registration of a multiview run gives, and how its
 * pairs are ranked, parsed once for every tool that ranks or registers such pairs, so that pairs
 * ranked and registered apart (pcl_tensor_pairs) equal those pcl_tensor_model ranks and registers.
 */
#pragma once

#include "tool_main.h"

#include <pcl/registration/multiview_tensor_registration.h>

namespace pcl_tensor_tools
{
  /** --faces N, --dims X,Y,Z, --dims-tolerance T (after ICP, locally, and over all views, globally)
    * and --rank-sample N into \a params; the other fields keep their values. */
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
    if (pcl::console::parse_argument (argc, argv, "--rank-sample", params.ranking.sample_tensors) >= 0 &&
        params.ranking.sample_tensors < 0)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--rank-sample takes a number of tensors per view (0: all), got "
                        << params.ranking.sample_tensors);
  }

  /** The help line of --rank-sample. */
  inline void
  printRankSampleHelp (const pcl::registration::MultiviewRegistrationParams& params)
  {
    pcl::console::print_info ("  --rank-sample N    tensors of each view matched to rank the pairs, 0 = all (default %d)\n",
                              params.ranking.sample_tensors);
  }
}
