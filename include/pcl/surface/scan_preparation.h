/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>
#include <pcl/features/scan_mesh_normals.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace pcl
{
  /** \brief Parameters of the range image -> M_i -> M'_i pipeline of Section 2, with the paper's defaults
    * (the stray-fragment and speck fields are beyond the paper); registration's own are registrationPreparation(). */
  struct ScanPreparationParams
  {
    /** Prune triangles with an edge longer than mean + k * stddev (Section 2: k = 0.6). */
    double edge_std_devs = 0.6;
    /** Faces of the reduced mesh M'_i (Sections 3 and 7.2: about 400).
      * \note Registration departs from this: registrationPreparation() reduces to 1000 faces, since at 400
      * too few reduced vertices recur between real views; see doc/design.md#more-faces-for-registration. */
    int target_faces = 400;
    /** How the normals of M'_i are computed (Section 2, approach (b) by default). */
    ScanMeshNormalEstimation::Method normal_method = ScanMeshNormalEstimation::Method::FINE_NEIGHBOURHOOD;
    /** Neighbourhood radius of approach (b), in units of d_res. */
    double normal_radius_resolutions = 3.0;
    /** Beyond the paper: fragments of M_i farther than this many d_res from the rest of the scan ... */
    double stray_fragment_gap = 20.0;
    /** ... and holding less than this fraction of its points are removed as stray returns
      * (removeStrayFragments(); 0 keeps every point). Eq. 1 and Eq. 9 take extents, which one stray
      * speck can set on its own.
      * \note Beyond the paper, which removes nothing; see doc/design.md#stray-fragment-removal. */
    double stray_fragment_fraction = 0.01;
    /** Beyond the paper: groups of at most this many pixels of an organized range image that stand in
      * front of the surface on every side are removed before triangulation (speckPixels(); 0 keeps
      * them). Like stray fragments, one speck can set Eq. 9's extents on its own.
      * \note Beyond the paper; see doc/design.md#speck-removal. */
    int speck_max_pixels = 9;
    /** ... and stand at least this many grid spacings in front of every neighbour. */
    double speck_jump = 3.0;
    /** Beyond the paper: Garland-Heckbert reduces the mesh of every this-many-th row and column of
      * an organized range image instead of M_i itself, when that mesh still has at least 4 points
      * per target face (1: M_i). The reduction's cost grows with its input, and M'_i keeps only a
      * small fraction of M_i's vertices, so the skipped points would be collapsed anyway.
      * \note The default 1 is the paper's; registrationPreparation() uses 2, which leaves every real
      * pair's outcome unchanged; see doc/design.md#reduction-from-every-second-row-and-column. */
    int reduction_grid_step = 1;
  };

  /** \brief One view, ready for tensor computation. */
  struct PreparedScan
  {
    ScanMesh fine;            ///< M_i, with face-average normals (NaN on vertices of no face)
    ScanMesh reduced;         ///< M'_i, with normals
    double resolution = 0.0;  ///< d_res of M_i: the mean edge length
    /** Noise of M_i's points (estimateScanNoise over neighbourhoods of 3 d_res), in its units. */
    double noise = 0.0;
  };

  /** \brief Run speck removal, triangulation, stray-fragment removal, reduction and normal estimation on one range image.
    * \throw InvalidScanException on unusable data, pcl::BadArgumentException on bad parameters
    */
  PreparedScan
  prepareScan (const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
               const ScanPreparationParams& params = {});

  /** \brief Check \a params as prepareScan() would, without a scan.
    * \throw pcl::BadArgumentException when one is out of range (e.g. fewer than 4 target faces)
    */
  void
  checkScanPreparationParams (const ScanPreparationParams& params);
}
