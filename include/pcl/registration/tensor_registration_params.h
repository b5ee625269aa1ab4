/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/registration/correspondence_estimation_tensor.h>
#include <pcl/registration/tensor_verification.h>
#include <pcl/surface/scan_preparation.h>

#include <functional>

namespace pcl
{
  namespace registration
  {
    /** \brief Mesh preparation for registration: Section 2's, at 1000 faces, reduced from every second
      * row and column of the range image.
      * \note Both depart from ScanPreparationParams' paper values (400 faces, M_i reduced whole): at 400
      * faces too few reduced vertices recur between real views, and the coarser grid reduces faster with
      * every real pair's outcome unchanged; see doc/design.md#more-faces-for-registration and
      * doc/design.md#reduction-from-every-second-row-and-column. */
    inline ScanPreparationParams
    registrationPreparation ()
    {
      ScanPreparationParams p;
      p.target_faces = 1000;
      p.reduction_grid_step = 2;
      return p;
    }

    /** \brief Every parameter of the pairwise pipeline, with the paper's values as defaults where it
      * gives one; each field that departs from it says so in a note (doc/design.md#departures-from-the-paper).
      * \ingroup registration
      */
    struct TensorRegistrationParams
    {
      /** Range image -> M_i -> M'_i (Section 2): registrationPreparation().
        * \note 1000 faces, not the paper's 400, at which too few reduced vertices recur between real
        * views for a correct tensor match to pass t_r and t_c; see doc/design.md#more-faces-for-registration. */
      ScanPreparationParams preparation = registrationPreparation ();
      /** Tensor grid N x N x N (Section 2: 10). */
      int grid_size = 10;
      /** Closest valid partners per vertex (Section 2: 3). */
      int partners_per_vertex = 3;
      /** Minimum mutual angle theta_d of a pair's normals, degrees (Section 2: 5). */
      double min_normal_angle = 5.0;
      /** Region growing over faces (the paper's method) rather than testing every face (default false).
        * \note Brute force is exact and faster on reduced meshes; see doc/design.md#face-visiting-by-brute-force. */
      bool region_growing = false;
      /** t_r, minimum overlap ratio R_O (Eq. 5; Section 4: 0.5). */
      float overlap_threshold = 0.5f;
      /** t_c, minimum correlation C_c (Eq. 6; Section 4: 0.5). */
      float correlation_threshold = 0.5f;
      /** When no match over t_r and t_c leads to a registration or a doubt and the hypothesis cap is
        * not reached, the matches over these lower thresholds that fell short of t_r or t_c are verified
        * next, best first (default 0.4 each; at or above t_r and t_c: no second round). A pair under half
        * overlap has few tensors whose cube the other view shows whole, so its true match often falls
        * just short of t_r or t_c; lowering them outright instead puts its hypotheses behind those of
        * pairs that register now, past the cap.
        * \note Beyond the paper; see doc/design.md#second-round-of-matches. */
      float fallback_overlap_threshold = 0.4f;
      float fallback_correlation_threshold = 0.4f;
      /** Delta theta_d of the index table, degrees (Section 2: 5). */
      double theta_bin_width = 5.0;
      /** The order in which matches are verified.
        * \note Fig. 7 verifies in SCENE_ORDER; best first tries the likeliest hypotheses first; see
        * doc/design.md#best-first-order. */
      TensorMatchOrder order = TensorMatchOrder::BEST_FIRST;
      /** The scene's tensors are computed in this many batches (every k-th vertex pair,
        * TensorEstimation::setPairBatch), each matched and its best matches verified before the next
        * is computed, as Fig. 7 computes scene tensors as they are needed (1: all at once). On a
        * symmetric object a batch's best match can be the turned pose; the ambiguity check refuses it.
        * \note Beyond the paper; see doc/design.md#scene-tensors-in-batches. */
      int scene_tensor_batches = 8;
      /** Matches of each batch verified before the next batch is computed (0: all of them). Those
        * left over from every batch are verified together once all are computed, in order, so that a
        * pair that needs many hypotheses meets them in nearly the order of a single batch.
        * \note Beyond the paper; see doc/design.md#scene-tensors-in-batches. */
      int batch_hypotheses = 10;
      /** Local verification (Section 4.1). */
      TensorVerificationParams verification;
      /** Hypotheses verified at most before giving up (0: all matches). Section 7.3 finds most
        * correct matches among the first 50 scene tensors; the cap bounds the time spent on views
        * that do not overlap.
        * \note The paper has no cap; see doc/design.md#hypothesis-cap-and-repeats. */
      int max_hypotheses = 300;
      /** A hypothesis within this rotation (degrees) and translation (d_res) of one that ICP already
        * refuted is skipped: ICP would take it to the same wrong minimum. 0 disables.
        * \note Beyond the paper; see doc/design.md#hypothesis-cap-and-repeats. */
      double repeat_rotation = 3.0;
      double repeat_translation = 3.0;
      /** Once a hypothesis passes, up to this many of the next hypotheses whose pose is far from it
        * (ambiguity_rotation, or the scene's centroid put mean(D)/2 away) are verified too. If one of
        * them also passes at a pose other than the first (beyond the repeat tolerances), the surfaces
        * fit in two ways (a symmetric object) and the pair is reported ambiguous, not registered.
        * 0 disables the check.
        * \note Beyond the paper; see doc/design.md#ambiguity-check. */
      int ambiguity_checks = 2;
      /** Hypotheses within this rotation (degrees) of the passed pose, putting the scene's centroid
        * within mean(D)/2 of where it does, are taken as leading to it and not checked: ICP takes them
        * back to the passed pose. A symmetry finer than this (a sixfold one, a cylinder's) is not
        * detected; see doc/design.md#ambiguity-check. */
      double ambiguity_rotation = 60.0;
      /** Once a pose passes, the poses a rival could take near it are probed too (rivalPoses(): moved
        * along the two motions its common part constrains least, turned along the least constrained
        * one's screw by up to a half turn (screwTurnPoses()), and turned half-way about that part's
        * principal axes), each refined by ICP and verified; and moved along the least constrained motion
        * just past another answer's distance, judged as it is (a valley of poses that D alone cuts
        * short). Of the poses that pass, the one with the most fine correspondences is kept; another
        * distinct one with enough of them (rival_margin) means the surfaces do not pin the pose down (a
        * surface of revolution, a plane, a cylinder, a twofold symmetry), and the pair is reported
        * ambiguous. false: no probe.
        * \note Beyond the paper; see doc/design.md#rival-probe. */
      bool probe_rivals = true;
      /** A distinct rival that passes with at least (1 - rival_margin) times the kept pose's fine
        * correspondences makes the pair ambiguous (default 1: any rival that passes). Fewer is not
        * safer: a pose turned along a surface of revolution gains correspondences where it turns the
        * views onto more of each other. */
      double rival_margin = 1.0;
      /** A rival with fewer fine correspondences than the kept pose is dismissed, not a doubt, when the
        * other sensor's background speaks against it alone: at least rival_empty_space_fraction of its
        * points seen by that sensor lie in front of its surface or where it saw nothing, more than this
        * many d_res from all of it (emptySpaceViolation()), twenty times the kept pose's fraction there.
        * A pose slid along a prismatic part fits the common surface as well as the truth does, but puts
        * the rest of one view over the other's background. 0 disables: every rival doubts.
        * \note Beyond the paper; see doc/design.md#rival-probe. */
      double rival_empty_space_margin = 4.0;
      /** See rival_empty_space_margin: a tenth of the seen points, ten times the free-space check's limit. */
      double rival_empty_space_fraction = 0.1;
      /** A rival that fails only the dimension checks (Eq. 9) is judged again with their tolerances
        * times this, and with the free-space check as strict as an answer's: two views of a round object
        * give a D short of it, and else the most compact of the poses a surface of revolution allows
        * passes alone, as its turns along the surface widen the union past D. 1: rivals are held to D as
        * answers are.
        * \note Beyond the paper; see doc/design.md#rival-probe. */
      double rival_dimension_factor = 1.5;
      /** The rivals' ICP pairs points whose normals differ by up to this many degrees (default 180:
        * all of them), where the answer's keeps TensorVerificationParams::icp_max_normal_angle. A rival
        * only has to show that a second pose fits, and the wider ICP reaches turned poses of a
        * near-symmetric object that the answer's narrower one stops short of.
        * \note Beyond the paper; see doc/design.md#compatible-normals. */
      double rival_icp_max_normal_angle = 180.0;
    };

    /** \brief Check every parameter of \a params before any work is done: the components' own
      * setters' ranges, a non-negative hypothesis cap and repeat tolerances.
      * \throw pcl::BadArgumentException naming the first value out of range
      */
    void
    checkParams (const TensorRegistrationParams& params);

    /** \brief A further test of a hypothesis that passed local verification, e.g. global verification
      * (Section 4.2; Fig. 7, steps 15-16): return false to refuse it, and the next tensor match is tried.
      * \param[in] result the locally verified hypothesis (result.transform: scene -> model, refined, between
      *            the views' own frames, as the registration reports it)
      */
    using HypothesisAcceptor = std::function<bool (const TensorVerificationResult& result)>;
  }
}
