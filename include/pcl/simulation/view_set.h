/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>
#include <pcl/simulation/zbuffer_range_renderer.h>
#include <Eigen/Geometry>

#include <utility>
#include <vector>

namespace pcl
{
  /** \brief Where the views of an object are taken from: unit directions from the object's centre
    * toward each sensor. The sensors of a view set all look at the centre.
    * \ingroup simulation
    */
  using ViewDirections = std::vector<Eigen::Vector3d, Eigen::aligned_allocator<Eigen::Vector3d>>;

  /** \brief Sensor poses (sensor frame -> model frame), one per view. */
  using SensorPoses = std::vector<Eigen::Affine3d, Eigen::aligned_allocator<Eigen::Affine3d>>;

  /** \brief The 26 view directions of Sections 6 and 7.1: 12 on the equator 30 degrees apart, 6 on
    * each of the rings at +60 and -60 degrees elevation (60 degrees of azimuth apart, so about 29
    * degrees apart on the sphere), and the 2 poles, which are 30 degrees from their ring.
    * \param[in] up the pole direction (default +y, the Stanford models' up axis)
    * \return 26 unit vectors: equator first (azimuth 0, 30, ...), then the +60 ring, the -60 ring,
    * the +pole and the -pole
    * \ingroup simulation
    */
  ViewDirections
  makeDefaultViewDirections (const Eigen::Vector3d& up = Eigen::Vector3d::UnitY ());

  /** \brief A turntable: \a count directions on a ring, \a step_deg degrees apart in azimuth.
    * \param[in] count number of views (> 0)
    * \param[in] step_deg azimuth step in degrees
    * \param[in] elevation_deg elevation of the ring above the equator, in degrees (|e| < 90)
    * \param[in] up the turntable axis
    * \throw pcl::BadArgumentException on count <= 0 or |elevation| >= 90
    * \ingroup simulation
    */
  ViewDirections
  makeRingViewDirections (int count, double step_deg, double elevation_deg = 0.0,
                          const Eigen::Vector3d& up = Eigen::Vector3d::UnitY ());

  /** \brief The sphere that a view set's sensors look at: the centre of the mesh's bounding box and
    * the largest distance from it to a vertex.
    * \ingroup simulation
    */
  struct ViewTarget
  {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
    double radius = 0.0;
  };

  /** \brief The bounding sphere of the mesh's vertices, centred on their bounding box.
    * \throw InvalidScanException when the mesh has no vertices
    */
  ViewTarget
  boundingTarget (const ScanMesh& mesh);

  /** \brief Distance from the target's centre at which the whole bounding sphere fits in the camera's
    * field of view (perspective: within the narrower of the horizontal and vertical angles), with
    * a margin factor. For an orthographic camera it is 2 radii (any distance outside works).
    * \throw pcl::BadArgumentException on a non-positive radius or margin < 1
    */
  double
  fittingDistance (const ViewTarget& target, const RangeCameraParams& camera, double margin = 1.05);

  /** \brief The orthographic extent that fits the target's bounding sphere, with a margin factor. */
  double
  fittingOrthoExtent (const ViewTarget& target, const RangeCameraParams& camera, double margin = 1.05);

  /** \brief Sensor poses looking at \a target.centre from \a distance along each direction. The sensor
    * looks down its -z axis (RangeCameraParams), so its +z axis is the direction itself; its y axis
    * is as close to \a up as possible (x when the direction is parallel to \a up).
    * \return one pose per direction, mapping sensor-frame points into the model frame
    * \ingroup simulation
    */
  SensorPoses
  lookAtPoses (const ViewDirections& directions, const ViewTarget& target, double distance,
               const Eigen::Vector3d& up = Eigen::Vector3d::UnitY ());

  /** \brief For each view, the indices of the views whose direction is within \a tolerance_deg of
    * \a angle_deg away (default: 30 +- 2 degrees, the paper's adjacent views).
    * \ingroup simulation
    */
  std::vector<std::vector<int>>
  viewNeighbours (const ViewDirections& directions, double angle_deg = 30.0, double tolerance_deg = 2.0);

  /** \brief The adjacent pairs (i < j) of viewNeighbours(), each pair once, sorted. */
  std::vector<std::pair<int, int>>
  adjacentViewPairs (const ViewDirections& directions, double angle_deg = 30.0, double tolerance_deg = 2.0);
}
