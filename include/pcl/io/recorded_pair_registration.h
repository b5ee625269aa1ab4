/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/io/view_pair_results.h>
#include <pcl/registration/multiview_tensor_registration.h>

#include <string>
#include <vector>

namespace pcl
{
  namespace io
  {
    /** \brief Pair registrations answered from results computed elsewhere (pcl_tensor_pairs, e.g. on a
      * cluster), for MultiviewTensorRegistration::setPairRegistration(): a pair registered the other way
      * round is turned around; a pair without a result goes to \a fallback (e.g. cachedPairRegistration()),
      * so that the registration is the one a single process gives. A search with fewer hypotheses than
      * the recorded one is answered as it would have ended (reportWithinHypotheses()).
      * \param[in] results the recorded registrations
      * \param[in] view_files the views' files, in the order of the registration's views (matched by viewIdOf())
      * \param[in] fallback registers a pair not recorded
      */
    pcl::registration::ViewPairRegistration
    recordedPairRegistration (const std::vector<ViewPairResult>& results, const std::vector<std::string>& view_files,
                              const pcl::registration::ViewPairRegistration& fallback);
  }
}
