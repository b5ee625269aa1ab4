/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/features/feature.h>
#include <pcl/features/tensor_descriptor.h>
#include <pcl/features/tensor_grid.h>
#include <pcl/Vertices.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace pcl
{
  /** \brief How the "closest three partners" rule of Section 2 turns into unordered pairs.
    * \ingroup features
    */
  enum class TensorPairing
  {
    /** Keep {i, j} when j is among i's closest valid partners OR i among j's: every vertex gets its
      * closest partners, as the paper says, and there are at most k n pairs. The default. */
    EITHER,
    /** Keep {i, j} only when each is among the other's closest valid partners: every vertex is in at
      * most k pairs. Fewer, more mutual tensors. */
    MUTUAL
  };

  /** \brief TensorEstimation computes the tensor representation of a reduced mesh M'_i (Mian,
    * Bennamoun & Owens, "A Novel Representation and Feature Matching Algorithm for Automatic Pairwise
    * Registration of Range Images", IJCV 66(1), 2006, Section 2).
    *
    * Inputs: the mesh vertices (setInputCloud), their normals (setInputNormals), the triangles
    * (setPolygons), and the distance limits and bin size, either from the object's dimensions D
    * (setObjectDimensions: Eq. 2 and Eq. 3) or explicitly (setDistanceLimits, setBinSize). If
    * indices are set (setIndices), pairs are formed among those vertices only; the whole mesh is still
    * binned. A separate search surface is not supported (the polygons index the input cloud).
    *
    * Output: one TensorDescriptor per valid vertex pair, pairs sorted by (min, max) vertex index.
    *
    * Pairing (Eq. 2 and the text after it): the distance between the two vertices lies in
    * [d_min, d_max]; the mutual angle theta_d of their normals is greater than the minimum angle
    * (5 degrees); their sum is defined (theta_d at most the maximum angle, 175 degrees by default so
    * that z is as well conditioned as x); each vertex is paired with its k = 3 closest valid partners
    * (TensorPairing::EITHER by default: at most 3 n pairs, none twice).
    *
    * Frame (Section 2): origin = midpoint; z = normalize(n_a + n_b); x = normalize(n_a x n_b);
    * y = z x x. Orthonormal and right-handed. Swapping a and b negates x and y (a half turn about z),
    * so the pair order must be defined geometrically, not by index (indices differ between views).
    * The canonical order puts the second vertex on the +z side: z . (p_b - p_a) >= 0. This is
    * invariant to rigid motions and to re-indexing. It is ill-conditioned when the segment is
    * nearly orthogonal to z (a symmetric pair, e.g. two points on a sphere); such tensors have
    * order_ambiguous = 1 (|z . (p_b - p_a)| < sin(ambiguity angle) |p_b - p_a|) and a matcher should
    * also try flipPairOrder() of one side. One tensor is still produced per pair.
    *
    * Bins: the exact area of the mesh inside each of the N^3 bins of the grid (see TensorSurfaceGrid).
    * By default every face whose bounding sphere and local bounding box meet the grid is clipped
    * (brute force: exact, and on reduced meshes of a few hundred to a thousand faces the fastest way).
    * setRegionGrowing(true) visits faces by the paper's region growing from the vertex closest to the
    * origin instead. The paper's rule (one seed; stop when the whole frontier is outside the grid)
    * misses surface that re-enters the grid, which on real scans is common, not "very slim[ly]"; so
    * region growing is by default also seeded in every connected component that can reach the grid
    * and grows through a guard band of twice the grid's half-extent (setSeedEveryComponent,
    * setGrowthMargin): it then agrees with brute force almost always, but visits more faces (it
    * scales better on large meshes). setSeedEveryComponent(false) and setGrowthMargin(0) give the
    * paper's rule exactly. See doc/design.md#face-visiting-by-brute-force.
    *
    * Errors: compute() follows PCL: on invalid input it prints PCL_ERROR, returns an empty cloud and
    * records the reason (getLastError()). computeOrThrow() throws instead: pcl::BadArgumentException for
    * missing or inconsistent parameters, pcl::InvalidScanException for unusable data (no polygons,
    * non-finite points, zero-length normals, ...). Setters throw pcl::BadArgumentException right away
    * for values that can never be valid (N = 0, D = 0, negative sizes).
    * \ingroup features
    */
  template <typename PointInT, typename PointNT, typename PointOutT = pcl::TensorDescriptor>
  class TensorEstimation : public FeatureFromNormals<PointInT, PointNT, PointOutT>
  {
    public:
      using Ptr = shared_ptr<TensorEstimation<PointInT, PointNT, PointOutT> >;
      using ConstPtr = shared_ptr<const TensorEstimation<PointInT, PointNT, PointOutT> >;
      using PointCloudOut = typename Feature<PointInT, PointOutT>::PointCloudOut;

      /** \brief Kind of the last error, to choose the exception computeOrThrow() throws. */
      enum class ErrorKind { NONE, BAD_ARGUMENT, INVALID_SCAN };

      /** \brief Empty constructor: the paper's defaults (N = 10, theta_d > 5 degrees, 3 partners),
        * brute-force face visiting (see setRegionGrowing). */
      TensorEstimation () { this->feature_name_ = "TensorEstimation"; }

      /** \brief Set the triangles of the mesh, as indices into the input cloud.
        * \param[in] polygons triangles (M'_i, Section 2) */
      void setPolygons (const std::vector<pcl::Vertices>& polygons) { polygons_ = polygons; }
      /** \brief The triangles of the mesh. */
      const std::vector<pcl::Vertices>& getPolygons () const { return polygons_; }

      /** \brief Set d_min = mean(D)/6, d_max = mean(D)/4 (Eq. 2) and b_s = mean(D)/30 (Eq. 3).
        * \param[in] dims the object's bounding dimensions D (Eq. 1)
        * \throw pcl::BadArgumentException when mean(D) is not positive and finite */
      void setObjectDimensions (const ObjectDimensions& dims);

      /** \brief Set the pairing distance limits (Eq. 2).
        * \param[in] d_min minimum distance between the two vertices of a pair
        * \param[in] d_max maximum distance
        * \throw pcl::BadArgumentException unless 0 < d_min <= d_max, finite */
      void setDistanceLimits (double d_min, double d_max);
      /** \brief d_min of Eq. 2 (0 until set). */
      double getMinDistance () const { return d_min_; }
      /** \brief d_max of Eq. 2 (0 until set). */
      double getMaxDistance () const { return d_max_; }

      /** \brief Set the bin size b_s (Eq. 3).
        * \param[in] bin_size edge of a cubic bin
        * \throw pcl::BadArgumentException unless positive and finite */
      void setBinSize (double bin_size);
      /** \brief b_s of Eq. 3 (0 until set). */
      double getBinSize () const { return bin_size_; }

      /** \brief Set the number of bins N per axis (Section 2: 10).
        * \param[in] grid_size N in [1, TENSOR_MAX_GRID_SIZE]
        * \throw pcl::BadArgumentException otherwise */
      void setGridSize (int grid_size);
      /** \brief N (default 10, Section 2). */
      int getGridSize () const { return grid_size_; }

      /** \brief Set the minimum mutual normal angle theta_d of a pair (Section 2: 5 degrees).
        * \param[in] degrees in [0, 180)
        * \throw pcl::BadArgumentException otherwise */
      void setMinNormalAngle (double degrees);
      /** \brief Minimum theta_d in degrees (default 5, Section 2). */
      double getMinNormalAngle () const { return min_normal_angle_; }

      /** \brief Set the maximum mutual normal angle: "the average of the two normals must be defined"
        * (Section 2). |n_a + n_b| = 2 cos(theta_d/2), so 175 degrees (the default) conditions z as the
        * 5 degree minimum conditions x.
        * \note The paper gives no value; see doc/design.md#canonical-pair-order.
        * \param[in] degrees in (0, 180)
        * \throw pcl::BadArgumentException otherwise */
      void setMaxNormalAngle (double degrees);
      /** \brief Maximum theta_d in degrees (default 175). */
      double getMaxNormalAngle () const { return max_normal_angle_; }

      /** \brief Set how many closest valid partners each vertex gets (Section 2: 3).
        * \param[in] partners at least 1
        * \throw pcl::BadArgumentException otherwise */
      void setPartnersPerVertex (int partners);
      /** \brief Partners per vertex (default 3, Section 2). */
      int getPartnersPerVertex () const { return partners_per_vertex_; }

      /** \brief Set how per-vertex partner lists become pairs (default TensorPairing::EITHER). */
      void setPairing (TensorPairing pairing) { pairing_ = pairing; }
      /** \brief The pairing rule. */
      TensorPairing getPairing () const { return pairing_; }

      /** \brief Compute the tensors of one batch of the pairs only: of the valid pairs in their sorted
        * order, every \a batches-th, starting at \a batch. The batches of one view partition its
        * tensors, spread evenly over the view. Fig. 7 computes the scene's tensors one at a time and
        * stops once one match verifies; a caller can do the same a batch at a time
        * (TensorRegistration does). Default: one batch, every pair. One estimation computing
        * the batches in turn meshes the surface and forms the pairs once: each compute() checks that
        * the input, the triangles and the settings are those of the last and redoes what changed.
        * \throw pcl::BadArgumentException unless 0 <= batch < batches */
      void setPairBatch (int batches, int batch)
      {
        if (batches < 1 || batch < 0 || batch >= batches)
          PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorEstimation::setPairBatch] batch " << batch << " of "
                            << batches << " is not one of the batches");
        pair_batches_ = batches;
        pair_batch_ = batch;
      }
      /** \brief Number of batches the pairs are split into, and the one computed. */
      int getPairBatches () const { return pair_batches_; }
      int getPairBatch () const { return pair_batch_; }

      /** \brief Set the angle below which the segment's elevation from the xy plane of the frame makes
        * the pair order ambiguous (order_ambiguous = 1). Not a paper parameter; default 5 degrees, the
        * size of the normal noise the paper allows for (Delta theta_d, Section 2).
        * \note Beyond the paper, which does not define the pair order; see doc/design.md#canonical-pair-order.
        * \param[in] degrees in [0, 90)
        * \throw pcl::BadArgumentException otherwise */
      void setOrderAmbiguityAngle (double degrees);
      /** \brief The order ambiguity angle in degrees (default 5). */
      double getOrderAmbiguityAngle () const { return order_ambiguity_angle_; }

      /** \brief Visit the faces by region growing (true: the paper's method, Section 2) or test every
        * face whose bounding sphere meets the grid (false, default; see the class notes).
        * \note The default departs from the paper: brute force is exact, never misses surface that
        * re-enters the grid, and is faster on reduced meshes; see doc/design.md#face-visiting-by-brute-force. */
      void setRegionGrowing (bool region_growing) { region_growing_ = region_growing; }
      /** \brief Whether region growing is used. */
      bool getRegionGrowing () const { return region_growing_; }

      /** \brief Region growing: also seed the closest vertex of every connected component of the mesh
        * that can reach the grid (true, default), or only the vertex closest to the origin (false: the
        * paper's single seed, Section 2). Scans split into components at depth discontinuities.
        * See TensorSurfaceGrid::setSeedEveryComponent.
        * \note The default departs from the paper's single seed; see doc/design.md#face-visiting-by-brute-force. */
      void setSeedEveryComponent (bool every) { seed_every_component_ = every; }
      /** \brief Whether every component that can reach the grid is seeded. */
      bool getSeedEveryComponent () const { return seed_every_component_; }

      /** \brief Region growing: continue through faces outside the grid within a guard band of
        * \a fraction times the grid's half-extent (default 2; 0: the paper's rule, which misses surface
        * that re-enters the grid). See TensorSurfaceGrid::setGrowthMargin.
        * \note The default departs from the paper; see doc/design.md#face-visiting-by-brute-force.
        * \throw pcl::BadArgumentException when negative */
      void setGrowthMargin (double fraction)
      {
        if (!(fraction >= 0.0) || !std::isfinite (fraction))
          PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorEstimation::setGrowthMargin] " << fraction
                            << " must be non-negative and finite");
        growth_margin_ = fraction;
      }
      /** \brief The guard band as a fraction of the grid's half-extent. */
      double getGrowthMargin () const { return growth_margin_; }

      /** \brief Faces whose local bounding box was tested, summed over the tensors of the last
        * compute() (the cost of face visiting: region growing against brute force). */
      std::size_t getFacesVisited () const { return faces_visited_; }
      /** \brief Faces that met a grid and were clipped, summed over the tensors of the last compute(). */
      std::size_t getFacesClipped () const { return faces_clipped_; }

      /** \brief Like compute(), but throw pcl::BadArgumentException or pcl::InvalidScanException
        * with the reason when the input is invalid, instead of returning an empty cloud.
        * \param[out] output one tensor per valid pair */
      void computeOrThrow (PointCloudOut& output);

      /** \brief Kind of the last error of compute() (ErrorKind::NONE after a success). */
      ErrorKind getLastErrorKind () const { return error_kind_; }
      /** \brief Message of the last error of compute() (empty after a success). */
      const std::string& getLastError () const { return error_message_; }

    protected:
      /** \brief Validate the inputs and parameters; on failure print PCL_ERROR, record the error,
        * clean up and return false. */
      bool initCompute () override;

      /** \brief Form the pairs and compute their tensors. */
      void computeFeature (PointCloudOut& output) override;

    private:
      /** The settings the pairs depend on: d_min, d_max, the normal angle limits, partners, pairing. */
      using PairSettings = std::tuple<double, double, double, double, int, TensorPairing>;

      bool fail (ErrorKind kind, const std::string& message, bool deinit);
      /** theta_d of vertices \a i and \a j, in degrees. */
      double normalAngle (int i, int j) const;
      /** Each vertex's closest valid partners (Eq. 2 and the angle limits of Section 2), as sorted pairs. */
      void formPairs ();
      PairSettings pairSettings () const
      {
        return {d_min_, d_max_, min_normal_angle_, max_normal_angle_, partners_per_vertex_, pairing_};
      }
      static bool samePolygons (const std::vector<pcl::Vertices>& a, const std::vector<pcl::Vertices>& b);

      std::vector<pcl::Vertices> polygons_;
      double d_min_{0.0};
      double d_max_{0.0};
      double bin_size_{0.0};
      int grid_size_{TENSOR_DEFAULT_GRID_SIZE};
      double min_normal_angle_{5.0};
      double max_normal_angle_{175.0};
      int partners_per_vertex_{3};
      TensorPairing pairing_{TensorPairing::EITHER};
      int pair_batches_{1};
      int pair_batch_{0};
      double order_ambiguity_angle_{5.0};
      bool region_growing_{false};
      bool seed_every_component_{true};
      double growth_margin_{2.0};

      std::size_t faces_visited_{0};
      std::size_t faces_clipped_{0};
      ErrorKind error_kind_{ErrorKind::NONE};
      std::string error_message_;
      std::vector<Eigen::Vector3d> vertices_;   // validated copies of the input, in double
      std::vector<Eigen::Vector3d> normals_unit_;
      TensorSurfaceGrid grid_;
      // Kept from one compute() to the next, and checked against the input each time: the batches of
      // one view (setPairBatch) then mesh the surface and form its pairs once.
      std::vector<pcl::Vertices> mesh_polygons_;  // the triangles grid_ holds
      std::vector<std::pair<int, int>> pairs_;    // the valid pairs, sorted
      pcl::Indices pairs_indices_;                // the indices and settings they were formed with
      PairSettings pairs_settings_;
      bool pairs_formed_{false};
  };

  /** \brief Compare two tensor clouds computed from the same input with different settings (e.g.
    * region growing against brute force): they must have the same pairs in the same order.
    * \param[in] a first cloud
    * \param[in] b second cloud
    * \param[in] tolerance two bins agree when |a - b| <= tolerance * b_s^2 (a fraction of a full bin
    *            face), and a bin missing from one side counts as zero
    * \return the number of tensors whose bins differ; pcl::BadArgumentException if the pairs differ
    * \ingroup features
    */
  std::size_t
  countDifferingTensors (const pcl::PointCloud<TensorDescriptor>& a, const pcl::PointCloud<TensorDescriptor>& b,
                         double tolerance = 1e-6);
}

#ifdef PCL_NO_PRECOMPILE
#include <pcl/features/impl/tensor.hpp>
#endif
