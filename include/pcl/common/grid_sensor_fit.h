/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace pcl
{
  /** \brief The outcome of fitting a pushbroom sensor to an organized scan (fitPushbroomSensor). */
  struct GridSensorFit
  {
    /** \brief True when a pushbroom explains the grid within the tolerance. */
    bool found = false;
    /** \brief The fitted sensor (meaningful only when found). */
    ScanViewpoint viewpoint;
    /** \brief RMS distance of the fan lines' points from their planes through the axis, over the median
      * spacing of neighbouring grid points. */
    double fan_rms = 0.0;
    /** \brief RMS spread of the other lines' points along the sweep, over the same spacing (each line's
      * even and odd cells apart, for a staggered sweep). */
    double sweep_rms = 0.0;
  };

  /** \brief Fit a pushbroom (line-scan) sensor to an organized range scan from its grid alone.
    *
    * A pushbroom sweeps a fan of lines of sight along a line: the grid lines of one kind (the fan
    * lines) lie in planes through one common axis along the sweep, and each line of the other kind
    * keeps one position along the sweep. The raw Stanford scans (Cyberware) are such: their rows lie
    * in planes through one line, and their columns in planes x = const, the odd rows half a column
    * over (doc/design.md#pushbroom-sensor-fit).
    * Both ways of assigning rows and columns are tried; the one whose fan fits better is kept.
    *
    * The fitted sensor's lines of sight are the scanner's own, which a perspective or an orthographic
    * model only approximates: it orients normals, projects points for Delaunay triangulation and
    * tells the free-space check and the volumetric integration where the sensor saw empty space.
    * \param[in] cloud an organized scan (NaN in empty cells)
    * \param[in] fan_tolerance largest accepted fan_rms
    * \param[in] sweep_tolerance largest accepted sweep_rms
    * \return the fit; found is false for an unorganized cloud, too few grid lines, or a grid that no
    *         pushbroom explains within the tolerances (a perspective grid of wide field, say)
    * \ingroup common
    */
  GridSensorFit
  fitPushbroomSensor (const pcl::PointCloud<pcl::PointXYZ>& cloud, double fan_tolerance = 0.25,
                      double sweep_tolerance = 0.25);
}
