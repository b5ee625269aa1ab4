/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#pragma once

#include <pcl/features/tensor_descriptor.h>
#include <pcl/memory.h>
#include <pcl/point_types.h>
#include <pcl/Vertices.h>
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl
{
  /** \brief The point-type independent core of TensorEstimation: the exact area of a triangle mesh
    * inside each bin of an N x N x N grid placed in a local frame (Section 2, Fig. 3(d)).
    *
    * Each candidate triangle is transformed into the local frame and split successively by the
    * axis-aligned bin planes with Sutherland-Hodgman half-plane splits: first along x (one convex
    * piece per x slab), then each piece along y, then along z. Every final piece lies in exactly one
    * bin and its area is added to that bin. This is exact up to floating-point rounding.
    *
    * Faces are visited either by the paper's region growing (start from the faces around the vertex
    * closest to the origin, and around the two pair vertices, and grow over shared vertices from every
    * face that meets the grid, stopping when the whole frontier lies outside; by default also from the
    * closest vertex of every other connected component that can reach the grid) or by brute force
    * (every face whose bounding sphere and then local bounding box meet the grid).
    *
    * Not thread-safe: one instance holds scratch buffers. Construct one per thread.
    * \ingroup features
    */
  class TensorSurfaceGrid
  {
    public:
      using Ptr = shared_ptr<TensorSurfaceGrid>;
      using ConstPtr = shared_ptr<const TensorSurfaceGrid>;

      /** \brief Statistics of the last computeBins() call. */
      struct Stats
      {
        int faces_visited = 0;  ///< faces whose local bounding box was tested
        int faces_clipped = 0;  ///< faces that met the grid and were clipped
      };

      /** \brief Set the mesh: vertices and triangles. Triangles with an index out of range or fewer
        * or more than three vertices are rejected with InvalidScanException; vertices on no face are
        * allowed (they are never used as region-growing seeds).
        * \param[in] vertices mesh vertices (finite)
        * \param[in] polygons triangles as indices into \a vertices
        * \throw InvalidScanException when there is no triangle or a triangle is malformed
        */
      void
      setMesh (const std::vector<Eigen::Vector3d>& vertices, const std::vector<pcl::Vertices>& polygons);

      /** \brief Number of triangles of the mesh (0 before setMesh). */
      std::size_t getNumFaces () const { return faces_.size (); }

      /** \brief Area of the mesh (sum of its triangles). */
      double getMeshArea () const { return mesh_area_; }

      /** \brief Set the grid: N bins per axis (Section 2, default 10) of size b_s (Eq. 3).
        * \throw pcl::BadArgumentException when N is not in [1, TENSOR_MAX_GRID_SIZE] or b_s <= 0
        */
      void
      setGrid (int grid_size, double bin_size);

      /** \brief Grid size N. */
      int getGridSize () const { return grid_size_; }
      /** \brief Bin size b_s. */
      double getBinSize () const { return bin_size_; }

      /** \brief Visit faces by region growing (true, the paper's method) or by brute force (false, default).
        * \note The default departs from the paper; see doc/design.md#face-visiting-by-brute-force. */
      void setRegionGrowing (bool region_growing) { region_growing_ = region_growing; }
      /** \brief Whether faces are visited by region growing. */
      bool getRegionGrowing () const { return region_growing_; }

      /** \brief Seed region growing in every connected component of the mesh that can reach the grid
        * (true, default), not only in the component of the vertex closest to the origin (false: the
        * paper's single seed). A range scan falls apart into components at depth discontinuities
        * (an ear in front of the head), and a grid often spans several of them; surface that leaves the
        * grid and re-enters it within one component is still missed.
        * \note The default departs from the paper; see doc/design.md#face-visiting-by-brute-force.
        */
      void setSeedEveryComponent (bool every) { seed_every_component_ = every; }
      /** \brief Whether every component that can reach the grid is seeded. */
      bool getSeedEveryComponent () const { return seed_every_component_; }

      /** \brief Let region growing continue through faces outside the grid but within a guard band of
        * \a fraction times the grid's half-extent around it (default 2; 0: the paper's rule, stop as
        * soon as the whole frontier is outside the grid). Catches surface that leaves the grid and
        * re-enters it: the wider the band, the closer region growing comes to brute force (test_tensor,
        * RegionGrowingAgreesWithBruteForceOnBunnyScans).
        * \note The default departs from the paper; see doc/design.md#face-visiting-by-brute-force.
        * \throw pcl::BadArgumentException when negative */
      void setGrowthMargin (double fraction);
      /** \brief The guard band, as a fraction of the grid's half-extent. */
      double getGrowthMargin () const { return growth_margin_fraction_; }

      /** \brief Number of connected components (over shared vertices) of the mesh's faces. */
      int getNumComponents () const { return static_cast<int> (component_reach_.size ()); }

      /** \brief Compute the sparse bins of the grid centred at \a origin with axes \a frame (rows).
        * \param[in] origin grid centre in mesh coordinates
        * \param[in] frame rows x, y, z of an orthonormal right-handed frame
        * \param[in] seed_a first pair vertex, used as an extra region-growing seed (-1: none)
        * \param[in] seed_b second pair vertex, used as an extra region-growing seed (-1: none)
        * \param[out] bin_index sorted linear indices (i_x N + i_y) N + i_z of the non-zero bins
        * \param[out] bin_area area inside each of those bins
        */
      void
      computeBins (const Eigen::Vector3d& origin, const Eigen::Matrix3d& frame, int seed_a, int seed_b,
                   std::vector<std::uint16_t>& bin_index, std::vector<float>& bin_area);

      /** \brief Statistics of the last computeBins() call. */
      const Stats& getStats () const { return stats_; }

    private:
      struct Polygon
      {
        static constexpr int capacity = 12;  // a triangle cut by six axis-aligned planes has at most 9 vertices
        double p[capacity][3];
        int n = 0;
      };

      bool visitFace (int face);
      template <int Axis> void sweep (const Polygon& poly, int flat_prefix);
      template <int Axis> static void split (const Polygon& in, double plane, Polygon& below, Polygon& above);
      void addArea (const Polygon& poly, int bin);
      const Eigen::Vector3d& localVertex (int v);

      // Mesh.
      std::vector<Eigen::Vector3d> vertices_;
      std::vector<std::array<int, 3>> faces_;
      std::vector<Eigen::Vector3d> face_normals_;      // unit normals (zero for degenerate faces)
      std::vector<Eigen::Vector3d> face_centres_;      // bounding sphere centres
      std::vector<double> face_radii_;                 // bounding sphere radii
      std::vector<int> vertex_face_offsets_;           // CSR: faces around each vertex
      std::vector<int> vertex_faces_;
      std::vector<int> face_vertices_;                 // vertices that lie on a face, grouped by component
      std::vector<int> component_offsets_;             // CSR: component c owns face_vertices_[offsets[c] .. offsets[c+1])
      std::vector<double> component_reach_;            // longest edge of the component's faces
      double mesh_area_{0.0};

      // Grid.
      int grid_size_{TENSOR_DEFAULT_GRID_SIZE};
      double bin_size_{0.0};
      double inv_bin_size_{0.0};
      bool region_growing_{false};
      bool seed_every_component_{true};
      double growth_margin_fraction_{2.0};
      double growth_margin_{0.0};

      // Scratch of the current tensor.
      Eigen::Vector3d origin_{Eigen::Vector3d::Zero ()};
      Eigen::Matrix3d frame_{Eigen::Matrix3d::Identity ()};
      double half_extent_{0.0};
      /** The face being clipped is measured on the coordinate plane it is steepest over: its pieces'
        * areas are their shoelace areas on the plane of axes (u, v), divided by |n_w| (w: the third). */
      int area_u_ = 0, area_v_ = 1;
      double area_scale_ = 0.5;
      std::vector<double> dense_;                       // N^3 accumulator, zero between calls
      std::vector<int> touched_;                        // bins made non-zero in this call, sorted
      std::vector<std::uint64_t> touched_bits_;         // bitmap of the same bins while accumulating
      std::vector<Eigen::Vector3d> local_;              // local coordinates, valid when stamp matches
      std::vector<std::uint32_t> local_stamp_;
      std::vector<std::uint32_t> face_stamp_;
      std::uint32_t stamp_{0};
      std::vector<int> queue_;
      Stats stats_;
  };
}
