/*
 * pcl_tensor evaluation: stability of the local frames after mesh reduction (Section 3, Figs. 4-5, Eq. 4).
 */
#pragma once

#include "eval_views.h"

#include <string>
#include <vector>

namespace pcl_tensor_eval
{
  /** \brief Vertices within this many d_res of a vertex of the other view correspond (Section 3: 2 d_res). */
  constexpr double kCorrespondingVertexResolutions = 2.0;

  /** \brief Section 3's experiment on one view pair, with the ground-truth alignment. */
  struct FrameStability
  {
    std::string model, scene;
    /** Eq. 14 on the fine meshes M_i and on the reduced meshes M'_i (vertices within 2 d_res). */
    double overlap_fine = 0.0, overlap_reduced = 0.0;
    std::size_t reduced_model_vertices = 0, reduced_scene_vertices = 0;
    /** Scene tensors both of whose vertices correspond to model vertices that also form a tensor. */
    std::size_t corresponding_tensors = 0;
    /** Of those, frames whose relative rotation B_m^T B_s is within each angle of the ground truth (Eq. 4). */
    std::size_t frames_within_5deg = 0, frames_within_10deg = 0;
    /** Fig. 4(d) and 5: each reduced scene vertex's distance to the nearest reduced model vertex, in d_res. */
    std::vector<double> nearest_vertex_res;
    /** Eq. 4 residual of every corresponding tensor pair: angle of B_m^T B_s R_GT^-1, degrees. */
    std::vector<double> frame_error_deg;
  };

  /** \brief Measure how many reduced vertices recur and how well corresponding vertex pairs give the
    * same frame, for two prepared views with ground truth.
    * \param[in] frame_vertex_resolutions for the frames (Eq. 4), vertices correspond within this many d_res
    *            (the overlaps always use kCorrespondingVertexResolutions)
    */
  FrameStability
  measureFrameStability (const EvalView& model, const EvalView& scene,
                         double frame_vertex_resolutions = kCorrespondingVertexResolutions);
}
