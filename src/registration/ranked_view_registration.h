/*
 * pcl_tensor: multiview registration of views in any order (private to the library).
 */
#pragma once

#include <pcl/registration/multiview_tensor_registration.h>

#include <algorithm>
#include <vector>

namespace pcl
{
  namespace registration
  {
    namespace detail
    {
      /** \brief The views whose poses are given (MultiviewInput::pose_known) and usable: they form one
        * group from the start, in the frame of their poses. */
      struct KnownPoses
      {
        std::vector<bool> known;  ///< per view
        ViewPoses poses;          ///< per view: the given pose when known

        bool any () const { return std::find (known.begin (), known.end (), true) != known.end (); }
      };

      /** \brief RANKED search: every pair of \a views (or only \a allowed ones) ranked by their tensors,
        * then registered best first while it joins two groups, each join checked by global
        * verification over both groups (Section 4.2). Fills the views' status (registered, reference,
        * component, pairwise poses), the joins, the candidates and the components of \a result.
        * \param[in] views each view with its tensors (null: unusable)
        * \param[in] known views with given poses: joined from the start, and only pairs with another view ranked
        * \param[in] scores scores known from before (may be empty) */
      void
      registerRankedViews (const MultiviewRegistrationParams& params, const ViewPairs& allowed,
                           const std::vector<TensorView::ConstPtr>& views, const KnownPoses& known,
                           const ViewPairRegistration& registration,
                           const ViewPairScoreCache& scores, unsigned threads, const MultiviewProgress& progress,
                           MultiviewRegistrationResult& result);
    }
  }
}
