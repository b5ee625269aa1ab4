/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace pcl
{
  /** \brief Turns a range image into the triangle mesh M_i of Section 2.
    *
    * Organized clouds are triangulated over their grid (the grid is the retinal plane); unorganized
    * clouds by a 2D Delaunay triangulation (a sweep-hull of our own) of the points projected onto
    * the sensor's retinal plane. Triangles with an edge longer than mean + k standard deviations are
    * then removed (k = 0.6 in the paper), which separates surfaces that the triangulation falsely
    * connected. The statistics are taken over each triangle's longest edge: over all edges, the
    * rule would remove every triangle of a regular grid, whose diagonals are sqrt(2) times longer.
    * A triangle whose longest edge is under a floor of 2 median lengths is always kept: where the
    * lengths barely vary (a tilted plane, a synthetic render) the standard deviation is rounding
    * noise, and mean + 0.6 stddev alone would cut into a smooth surface (doc/design.md#edge-pruning).
    * Delaunay triangulates the convex hull of the projected points, so it also spans the scan's gaps
    * (shadows, holes, the hollows of the silhouette) with triangles that a grid never forms. They
    * would inflate the statistics and let the shorter fills survive, so they are left out
    * of them, though they still face the threshold. A range sensor samples its retinal plane evenly,
    * which is how they are recognised: their longest retinal edge exceeds 1.5 median lengths
    * (setGapRetinalMedians; doc/design.md#delaunay-gap-triangles).
    * Vertices that no longer belong to any triangle are kept, so that the mesh has one vertex per
    * finite input point.
    * The faces are consistently oriented, most of the area facing the sensor; a triangle folded over
    * by noise faces away rather than breaking the orientation of its neighbours.
    * \ingroup surface
    */
  class RangeScanTriangulation
  {
    public:
      /** \brief Set k in the pruning threshold mean + k * stddev of the triangles' longest edges (default 0.6).
        * \note k is the paper's, but the statistic is over each triangle's longest edge, not over all edges,
        * which would prune every triangle of a regular grid; see doc/design.md#edge-pruning. */
      void setEdgeStdDevs (double k);
      double getEdgeStdDevs () const { return edge_std_devs_; }

      /** \brief Never prune a triangle whose longest edge is under this many median lengths (default 2).
        * \note Beyond the paper: where edge lengths barely vary the stddev is rounding noise, and the rule
        * alone would cut smooth surface; see doc/design.md#edge-pruning. */
      void setEdgeFloorMedians (double floor);
      double getEdgeFloorMedians () const { return edge_floor_medians_; }

      /** \brief A Delaunay triangle whose longest edge on the retinal plane exceeds this many median
        * lengths spans a gap in the scan, and is left out of the pruning statistics (default 1.5;
        * infinity takes every triangle into them, as Section 2 states the rule). Grids have no such
        * triangles. \note Beyond the paper: Delaunay's fills across gaps would inflate the statistics;
        * see doc/design.md#delaunay-gap-triangles. \throw BadArgumentException when under 1 */
      void setGapRetinalMedians (double k);
      double getGapRetinalMedians () const { return gap_retinal_medians_; }

      /** \brief Set the sensor; it defines the retinal plane for unorganized clouds. */
      void setViewpoint (const ScanViewpoint& viewpoint) { viewpoint_ = viewpoint; }
      const ScanViewpoint& getViewpoint () const { return viewpoint_; }

      /** \brief Force the Delaunay path even for organized clouds (default false). */
      void setForceDelaunay (bool force) { force_delaunay_ = force; }
      bool getForceDelaunay () const { return force_delaunay_; }

      /** \brief Triangulate \a cloud into \a mesh (normals zero, viewpoint copied).
        * \throw InvalidScanException with fewer than three finite points, or when every point lies on
        * one line in the retinal plane so that no triangle exists
        */
      void triangulate (const pcl::PointCloud<pcl::PointXYZ>& cloud, ScanMesh& mesh) const;

    private:
      double edge_std_devs_{0.6};
      double edge_floor_medians_{2.0};
      double gap_retinal_medians_{1.5};
      bool force_delaunay_{false};
      ScanViewpoint viewpoint_ = ScanViewpoint::fromPositiveZ ();
  };
}
