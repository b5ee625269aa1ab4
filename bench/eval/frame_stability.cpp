/*
 * pcl_tensor evaluation: stability of the local frames after mesh reduction (Section 3, Figs. 4-5, Eq. 4).
 */
#include "frame_stability.h"
#include "pair_evaluation.h"

#include <pcl/common/io.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/registration/tensor_match.h>

#include <cmath>
#include <map>
#include <utility>

namespace pcl_tensor_eval
{
  namespace
  {
    /** The reduced vertices of a view in the common frame. */
    pcl::PointCloud<pcl::PointXYZ>::Ptr
    reducedInCommonFrame (const EvalView& view)
    {
      pcl::PointCloud<pcl::PointXYZ>::Ptr points (new pcl::PointCloud<pcl::PointXYZ>);
      pcl::copyPointCloud (*view.prepared->reduced.cloud, *points);
      for (auto& p : *points)
        p.getVector3fMap () = (view.pose * p.getVector3fMap ().cast<double> ()).cast<float> ();
      return points;
    }

    pcl::PointCloud<pcl::PointXYZ>
    xyz (const pcl::PointCloud<pcl::PointNormal>& cloud)
    {
      pcl::PointCloud<pcl::PointXYZ> points;
      pcl::copyPointCloud (cloud, points);
      return points;
    }

    /** For each scene vertex, its nearest model vertex (or -1 beyond \a max_distance), and the distances. */
    std::vector<int>
    correspondingVertices (const EvalView& model, const EvalView& scene, double max_distance, std::vector<double>& distances)
    {
      const auto model_points = reducedInCommonFrame (model);
      const auto scene_points = reducedInCommonFrame (scene);
      pcl::KdTreeFLANN<pcl::PointXYZ> tree;
      tree.setInputCloud (model_points);
      pcl::Indices index (1);
      std::vector<float> sq (1);
      std::vector<int> match (scene_points->size (), -1);
      for (std::size_t i = 0; i < scene_points->size (); ++i)
        if (tree.nearestKSearch ((*scene_points)[i], 1, index, sq) == 1)
        {
          distances.push_back (std::sqrt (sq[0]));
          if (std::sqrt (sq[0]) <= max_distance)
            match[i] = index[0];
        }
      return match;
    }
  }

  FrameStability
  measureFrameStability (const EvalView& model, const EvalView& scene, double frame_vertex_resolutions)
  {
    FrameStability f;
    f.model = model.name;
    f.scene = scene.name;
    const double d_res = pairResolution (model, scene);
    const double max_distance = kCorrespondingVertexResolutions * d_res;
    f.overlap_fine = pairOverlap (model, scene);
    f.overlap_reduced = pcl::viewOverlap (xyz (*model.prepared->reduced.cloud), model.pose, xyz (*scene.prepared->reduced.cloud),
                                          scene.pose, max_distance);
    f.reduced_model_vertices = model.prepared->reduced.cloud->size ();
    f.reduced_scene_vertices = scene.prepared->reduced.cloud->size ();

    std::vector<double> distances;
    const std::vector<int> match = correspondingVertices (model, scene, frame_vertex_resolutions * d_res, distances);
    for (double d : distances)
      f.nearest_vertex_res.push_back (d / d_res);

    std::map<std::pair<int, int>, int> model_tensor_of;  // (vertex_a, vertex_b) -> model tensor
    for (std::size_t t = 0; t < model.tensors->size (); ++t)
      model_tensor_of[{(*model.tensors)[t].vertex_a, (*model.tensors)[t].vertex_b}] = static_cast<int> (t);
    const Eigen::Matrix3d truth = groundTruth (model, scene).rotation ();
    for (const pcl::TensorDescriptor& s : *scene.tensors)
    {
      const int a = match[s.vertex_a], b = match[s.vertex_b];
      if (a < 0 || b < 0)
        continue;
      // The model tensor of the same vertex pair, in either order; the order that the vertex
      // correspondence implies decides whether the scene frame is taken as is or flipped.
      auto same = model_tensor_of.find ({a, b});
      auto swapped = model_tensor_of.find ({b, a});
      if (same == model_tensor_of.end () && swapped == model_tensor_of.end ())
        continue;
      const bool flip = same == model_tensor_of.end ();
      const pcl::TensorDescriptor& m = (*model.tensors)[flip ? swapped->second : same->second];
      const Eigen::Matrix4f t = pcl::registration::transformFromTensorPair (m, flip ? pcl::flipPairOrder (s) : s);
      const double error = pcl::rotationErrorDeg (t.topLeftCorner<3, 3> ().cast<double> (), truth);
      ++f.corresponding_tensors;
      f.frames_within_5deg += error <= 5.0;
      f.frames_within_10deg += error <= 10.0;
      f.frame_error_deg.push_back (error);
    }
    return f;
  }
}
