/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>

#include <vector>

namespace pcl
{
  /** \brief Which points of a scan belong to stray fragments: groups of points far from the rest of
    * the scan and too small to be part of the object (a speck of the stand or a spurious return).
    *
    * The points are grouped by proximity on a grid of cells \a gap wide: points in the same or in
    * neighbouring cells (26-neighbourhood) fall into one group. Points closer than \a gap therefore
    * always share a group, and groups are at least \a gap apart. A group with fewer than
    * \a max_fraction of the finite points is stray; the largest group never is.
    *
    * Why it matters: Eq. 1 takes D as the largest principal extents of any single view, and the
    * dimension checks of Eq. 9 compare registered views with D, so one speck can set D alone and make
    * verification refuse correctly registered views (doc/design.md#stray-fragment-removal).
    * \param[in] points the scan's points (NaN points are never stray)
    * \param[in] gap grouping distance (> 0), e.g. 20 d_res
    * \param[in] max_fraction groups with fewer than this fraction of the points are stray, in [0, 1)
    * \return one flag per point, true for a stray point
    * \throw pcl::BadArgumentException on a non-positive \a gap or a fraction outside [0, 1)
    * \ingroup surface
    */
  std::vector<bool>
  strayFragmentPoints (const pcl::PointCloud<pcl::PointNormal>& points, double gap, double max_fraction);

  /** \brief Remove the stray fragments (strayFragmentPoints()) of a scan mesh: their vertices and the
    * faces that use them. The kept vertices keep their order, normals and viewpoint.
    * \return the number of vertices removed
    */
  std::size_t
  removeStrayFragments (ScanMesh& mesh, double gap, double max_fraction);
}
