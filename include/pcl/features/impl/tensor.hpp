/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#pragma once

#include <pcl/features/tensor.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::setObjectDimensions (const ObjectDimensions& dims)
{
  const double mean = dims.mean ();
  if (!(mean > 0.0) || !std::isfinite (mean))
    PCL_TENSOR_THROW (BadArgumentException, "[pcl::" << this->getClassName () << "::setObjectDimensions] mean(D) = "
                      << mean << " must be positive and finite (Eq. 2, Eq. 3)");
  d_min_ = dims.dMin ();
  d_max_ = dims.dMax ();
  bin_size_ = dims.binSize ();
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::setDistanceLimits (double d_min, double d_max)
{
  if (!(d_min > 0.0) || !(d_max >= d_min) || !std::isfinite (d_max))
    PCL_TENSOR_THROW (BadArgumentException, "[pcl::" << this->getClassName () << "::setDistanceLimits] need 0 < d_min <= d_max, got "
                      << d_min << ", " << d_max);
  d_min_ = d_min;
  d_max_ = d_max;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::setBinSize (double bin_size)
{
  if (!(bin_size > 0.0) || !std::isfinite (bin_size))
    PCL_TENSOR_THROW (BadArgumentException, "[pcl::" << this->getClassName () << "::setBinSize] bin size " << bin_size
                      << " must be positive and finite");
  bin_size_ = bin_size;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::setGridSize (int grid_size)
{
  if (grid_size < 1 || grid_size > TENSOR_MAX_GRID_SIZE)
    PCL_TENSOR_THROW (BadArgumentException, "[pcl::" << this->getClassName () << "::setGridSize] N = " << grid_size
                      << " is outside [1, " << TENSOR_MAX_GRID_SIZE << "]");
  grid_size_ = grid_size;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::setMinNormalAngle (double degrees)
{
  if (!(degrees >= 0.0 && degrees < 180.0))
    PCL_TENSOR_THROW (BadArgumentException, "[pcl::" << this->getClassName () << "::setMinNormalAngle] "
                      << degrees << " is outside [0, 180)");
  min_normal_angle_ = degrees;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::setMaxNormalAngle (double degrees)
{
  if (!(degrees > 0.0 && degrees < 180.0))
    PCL_TENSOR_THROW (BadArgumentException, "[pcl::" << this->getClassName () << "::setMaxNormalAngle] "
                      << degrees << " is outside (0, 180)");
  max_normal_angle_ = degrees;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::setPartnersPerVertex (int partners)
{
  if (partners < 1)
    PCL_TENSOR_THROW (BadArgumentException, "[pcl::" << this->getClassName () << "::setPartnersPerVertex] "
                      << partners << " must be at least 1");
  partners_per_vertex_ = partners;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::setOrderAmbiguityAngle (double degrees)
{
  if (!(degrees >= 0.0 && degrees < 90.0))
    PCL_TENSOR_THROW (BadArgumentException, "[pcl::" << this->getClassName () << "::setOrderAmbiguityAngle] "
                      << degrees << " is outside [0, 90)");
  order_ambiguity_angle_ = degrees;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> bool
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::fail (ErrorKind kind, const std::string& message, bool deinit)
{
  error_kind_ = kind;
  error_message_ = "[pcl::" + this->getClassName () + "::initCompute] " + message;
  PCL_ERROR ("%s\n", error_message_.c_str ());
  if (deinit)
    Feature<PointInT, PointOutT>::deinitCompute ();
  return false;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> bool
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::initCompute ()
{
  error_kind_ = ErrorKind::NONE;
  error_message_.clear ();
  const auto& input = this->input_;
  const auto& normals = this->normals_;
  if (!input)
    return fail (ErrorKind::BAD_ARGUMENT, "no input cloud was given (setInputCloud)", false);
  if (!normals)
    return fail (ErrorKind::BAD_ARGUMENT, "no normals were given (setInputNormals)", false);
  if (this->surface_ && this->surface_ != input)
    return fail (ErrorKind::BAD_ARGUMENT, "a search surface other than the input is not supported: the polygons "
                 "index the input cloud", false);
  if (input->empty ())
    return fail (ErrorKind::INVALID_SCAN, "the input cloud is empty", false);
  if (normals->size () != input->size ())
  {
    std::ostringstream s;
    s << "the input has " << input->size () << " points but " << normals->size () << " normals";
    return fail (ErrorKind::INVALID_SCAN, s.str (), false);
  }
  if (polygons_.empty ())
    return fail (ErrorKind::INVALID_SCAN, "the mesh has no polygons (setPolygons): tensors need a surface", false);
  if (!(d_max_ > 0.0) || !(bin_size_ > 0.0))
    return fail (ErrorKind::BAD_ARGUMENT, "distance limits and bin size are not set: call setObjectDimensions, "
                 "or setDistanceLimits and setBinSize (Eq. 2, Eq. 3)", false);

  // The pair search is a radius search of d_max on the vertices (Feature's search machinery).
  this->search_radius_ = d_max_ * (1.0 + 1e-6);
  this->k_ = 0;
  // Feature rebuilds the search tree only for another cloud; one changed in place needs it here too.
  const auto searched = this->tree_ ? this->tree_->getInputCloud () : nullptr;
  if (!FeatureFromNormals<PointInT, PointNT, PointOutT>::initCompute ())
    return fail (ErrorKind::BAD_ARGUMENT, "PCL feature initialisation failed (see the message above: indices?)", false);
  const bool tree_rebuilt = searched != this->surface_;

  const std::size_t n = input->size ();
  std::vector<Eigen::Vector3d> vertices (n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const PointInT& p = (*input)[i];
    if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
    {
      std::ostringstream s;
      s << "vertex " << i << " is not finite";
      return fail (ErrorKind::INVALID_SCAN, s.str (), true);
    }
    vertices[i] = Eigen::Vector3d (p.x, p.y, p.z);
  }
  std::vector<Eigen::Vector3d> unit_normals (n, Eigen::Vector3d::Zero ());
  for (const auto i : *this->indices_)
  {
    const PointNT& q = (*normals)[i];
    const Eigen::Vector3d nv (q.normal_x, q.normal_y, q.normal_z);
    const double len = nv.norm ();
    if (!std::isfinite (len) || len < 1e-6)
    {
      std::ostringstream s;
      s << "the normal of vertex " << i << " is " << (std::isfinite (len) ? "of zero length" : "not finite")
        << ": every vertex that may be paired needs a normal (Section 2)";
      return fail (ErrorKind::INVALID_SCAN, s.str (), true);
    }
    unit_normals[i] = nv / len;
  }
  // The batches of one view (setPairBatch) share its mesh and its pairs: only what changed is set up again.
  const bool same_vertices = vertices == vertices_;
  const bool same_surface = same_vertices && samePolygons (polygons_, mesh_polygons_);
  if (!same_vertices && !tree_rebuilt)
    this->tree_->setInputCloud (this->surface_);
  if (!same_vertices || unit_normals != normals_unit_ || *this->indices_ != pairs_indices_ || pairSettings () != pairs_settings_)
    pairs_formed_ = false;
  vertices_.swap (vertices);
  normals_unit_.swap (unit_normals);
  try
  {
    if (!same_surface)
    {
      mesh_polygons_.clear ();
      grid_.setMesh (vertices_, polygons_);
      mesh_polygons_ = polygons_;
    }
    grid_.setGrid (grid_size_, bin_size_);
  }
  catch (const InvalidScanException& e)
  {
    return fail (ErrorKind::INVALID_SCAN, errorDescription (e), true);
  }
  catch (const BadArgumentException& e)
  {
    return fail (ErrorKind::BAD_ARGUMENT, errorDescription (e), true);
  }
  grid_.setRegionGrowing (region_growing_);
  grid_.setSeedEveryComponent (seed_every_component_);
  grid_.setGrowthMargin (growth_margin_);
  return true;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::computeOrThrow (PointCloudOut& output)
{
  this->compute (output);
  if (error_kind_ == ErrorKind::BAD_ARGUMENT)
    throw BadArgumentException (error_message_);
  if (error_kind_ == ErrorKind::INVALID_SCAN)
    throw InvalidScanException (error_message_);
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> bool
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::samePolygons (const std::vector<pcl::Vertices>& a,
                                                                   const std::vector<pcl::Vertices>& b)
{
  return std::equal (a.begin (), a.end (), b.begin (), b.end (),
                     [] (const pcl::Vertices& p, const pcl::Vertices& q) { return p.vertices == q.vertices; });
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> double
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::normalAngle (int i, int j) const
{
  const Eigen::Vector3d& a = normals_unit_[i];
  const Eigen::Vector3d& b = normals_unit_[j];
  return std::atan2 (a.cross (b).norm (), a.dot (b)) * (180.0 / M_PI);
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::formPairs ()
{
  const auto& input = *this->input_;
  const std::size_t n = input.size ();
  std::vector<char> candidate (n, 0);
  for (const auto i : *this->indices_)
    candidate[i] = 1;

  // Each vertex's closest valid partners (Eq. 2 and the angle constraints of Section 2).
  std::vector<std::pair<int, int>> directed;
  directed.reserve (static_cast<std::size_t> (partners_per_vertex_) * this->indices_->size ());
  pcl::Indices nn;
  std::vector<float> nn_dist;
  std::vector<std::pair<double, int>> valid;
  for (const auto idx : *this->indices_)
  {
    const int i = static_cast<int> (idx);
    this->tree_->radiusSearch (input[i], this->search_radius_, nn, nn_dist);
    valid.clear ();
    for (const auto jdx : nn)
    {
      const int j = static_cast<int> (jdx);
      if (j == i || !candidate[j])
        continue;
      const double d = (vertices_[i] - vertices_[j]).norm ();
      if (d < d_min_ || d > d_max_)
        continue;
      const double theta = normalAngle (i, j);
      if (!(theta > min_normal_angle_) || theta > max_normal_angle_)
        continue;
      valid.emplace_back (d, j);
    }
    const std::size_t keep = std::min (valid.size (), static_cast<std::size_t> (partners_per_vertex_));
    std::partial_sort (valid.begin (), valid.begin () + keep, valid.end ());
    for (std::size_t k = 0; k < keep; ++k)
      directed.emplace_back (std::min (i, valid[k].second), std::max (i, valid[k].second));
  }
  std::sort (directed.begin (), directed.end ());
  pairs_.clear ();
  pairs_.reserve (directed.size ());
  for (std::size_t k = 0; k < directed.size ();)
  {
    std::size_t e = k;
    while (e < directed.size () && directed[e] == directed[k])
      ++e;
    if (pairing_ == TensorPairing::EITHER || e - k >= 2)
      pairs_.push_back (directed[k]);
    k = e;
  }
  pairs_indices_ = *this->indices_;
  pairs_settings_ = pairSettings ();
  pairs_formed_ = true;
}

//////////////////////////////////////////////////////////////////////////////////////////////
template <typename PointInT, typename PointNT, typename PointOutT> void
pcl::TensorEstimation<PointInT, PointNT, PointOutT>::computeFeature (PointCloudOut& output)
{
  if (!pairs_formed_)
    formPairs ();
  // One tensor per pair of this batch: frame (Section 2), canonical order, bins.
  const double rad2deg = 180.0 / M_PI;
  const double sin_ambiguity = std::sin (order_ambiguity_angle_ / rad2deg);
  output.clear ();
  const auto stride = static_cast<std::size_t> (pair_batches_);
  output.reserve (pairs_.size () / stride + 1);
  faces_visited_ = 0;
  faces_clipped_ = 0;
  for (std::size_t k = static_cast<std::size_t> (pair_batch_); k < pairs_.size (); k += stride)
  {
    const auto& pr = pairs_[k];
    int a = pr.first, b = pr.second;
    const Eigen::Vector3d z = (normals_unit_[a] + normals_unit_[b]).normalized ();
    Eigen::Vector3d d = vertices_[b] - vertices_[a];
    const double elevation = z.dot (d);
    if (elevation < 0.0)
    {
      std::swap (a, b);
      d = -d;
    }
    const Eigen::Vector3d x = normals_unit_[a].cross (normals_unit_[b]).normalized ();
    const Eigen::Vector3d y = z.cross (x);
    Eigen::Matrix3d frame;
    frame.row (0) = x;
    frame.row (1) = y;
    frame.row (2) = z;
    const Eigen::Vector3d origin = 0.5 * (vertices_[a] + vertices_[b]);

    PointOutT t;
    t.x = static_cast<float> (origin.x ());
    t.y = static_cast<float> (origin.y ());
    t.z = static_cast<float> (origin.z ());
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        t.rf[3 * r + c] = static_cast<float> (frame (r, c));
    t.theta_d = static_cast<float> (normalAngle (a, b));
    t.bin_size = static_cast<float> (bin_size_);
    t.vertex_a = a;
    t.vertex_b = b;
    t.grid_size = grid_size_;
    t.order_ambiguous = std::abs (elevation) < sin_ambiguity * d.norm () ? 1u : 0u;
    grid_.computeBins (origin, frame, a, b, t.bin_index, t.bin_area);
    faces_visited_ += static_cast<std::size_t> (grid_.getStats ().faces_visited);
    faces_clipped_ += static_cast<std::size_t> (grid_.getStats ().faces_clipped);
    output.emplace_back (std::move (t));
  }
  output.width = static_cast<std::uint32_t> (output.size ());
  output.height = 1;
  output.is_dense = true;
}

#define PCL_INSTANTIATE_TensorEstimation(T,NT,OutT) template class PCL_EXPORTS pcl::TensorEstimation<T,NT,OutT>;
