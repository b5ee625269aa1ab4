/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>
#include <pcl/simulation/zbuffer_range_renderer.h>
#include <Eigen/Geometry>

#include <utility>
#include <cstdint>
#include <vector>

namespace pcl
{
  /** \brief Where the views of an object are taken from: unit directions from the object's centre
    * toward each sensor. The sensors of a view set all look at the centre.
    * \ingroup simulation
    */
  using ViewDirections = std::vector<Eigen::Vector3d, Eigen::aligned_allocator<Eigen::Vector3d>>;

  /** \brief Sensor poses (sensor frame -> model frame), one per view; also the explicit form of a view set.
    * \ingroup simulation
    */
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

  /** \brief \a count directions uniform on the sphere (std::mt19937 of \a seed, normalised Gaussian
    * vectors): views from anywhere, as a hand-held scanner takes them.
    * \throw pcl::BadArgumentException on count < 0
    * \ingroup simulation
    */
  ViewDirections
  makeRandomViewDirections (int count, std::uint32_t seed);

  /** \brief The sphere that a view set's sensors look at: the centre of the mesh's bounding box and
    * the largest distance from it to a vertex.
    * \ingroup simulation
    */
  struct ViewTarget
  {
    /** The point every sensor looks at. */
    Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
    /** Radius of the sphere around \a centre that holds the whole model. */
    double radius = 0.0;
  };

  /** \brief The bounding sphere of the mesh's vertices, centred on their bounding box.
    * \param[in] mesh the model
    * \return its centre and radius
    * \ingroup simulation
    * \throw InvalidScanException when the mesh has no vertices
    */
  ViewTarget
  boundingTarget (const ScanMesh& mesh);

  /** \brief Distance from the target's centre at which the whole bounding sphere fits in the camera's
    * field of view (perspective: within the narrower of the horizontal and vertical angles), with
    * a margin factor. For an orthographic camera it is 2 radii (any distance outside works).
    * \param[in] target the model's bounding sphere
    * \param[in] camera the camera (size and field of view)
    * \param[in] margin how much larger than the sphere the view is (>= 1)
    * \return the distance from the centre to the sensor
    * \ingroup simulation
    * \throw pcl::BadArgumentException on a non-positive radius or margin < 1
    */
  double
  fittingDistance (const ViewTarget& target, const RangeCameraParams& camera, double margin = 1.05);

  /** \brief The orthographic extent (image width in metres) that fits the target's bounding sphere.
    * \param[in] target the model's bounding sphere
    * \param[in] camera the camera (its aspect ratio is used)
    * \param[in] margin how much larger than the sphere the view is (>= 1)
    * \return the value for RangeCameraParams::ortho_extent
    * \throw pcl::BadArgumentException on a non-positive radius or margin < 1
    * \ingroup simulation
    */
  double
  fittingOrthoExtent (const ViewTarget& target, const RangeCameraParams& camera, double margin = 1.05);

  /** \brief Sensor poses looking at \a target.centre from \a distance along each direction. The sensor
    * looks down its -z axis (RangeCameraParams), so its +z axis is the direction itself; its y axis
    * is as close to \a up as possible (x when the direction is parallel to \a up).
    * \param[in] directions unit directions from the centre toward each sensor
    * \param[in] target what the sensors look at
    * \param[in] distance from the centre to each sensor
    * \param[in] up the image's up direction
    * \return one pose per direction, mapping sensor-frame points into the model frame
    * \ingroup simulation
    */
  SensorPoses
  lookAtPoses (const ViewDirections& directions, const ViewTarget& target, double distance,
               const Eigen::Vector3d& up = Eigen::Vector3d::UnitY ());

  /** \brief For each view, the indices of the views whose direction is within \a tolerance_deg of
    * \a angle_deg away (default: 30 +- 2 degrees, the paper's adjacent views).
    *
    * Note that in the default set this links each ring to its pole and the equator only to itself: the
    * rings are about 64 degrees from the equator, so the 30-degree graph has three components.
    * \param[in] directions the view directions
    * \param[in] angle_deg the angle between neighbours, in degrees
    * \param[in] tolerance_deg the accepted deviation from \a angle_deg
    * \return for each view, its neighbours' indices in increasing order
    * \ingroup simulation
    */
  std::vector<std::vector<int>>
  viewNeighbours (const ViewDirections& directions, double angle_deg = 30.0, double tolerance_deg = 2.0);

  /** \brief The adjacent pairs (i < j) of viewNeighbours(), each pair once, sorted: the pairs to register.
    * \ingroup simulation
    */
  std::vector<std::pair<int, int>>
  adjacentViewPairs (const ViewDirections& directions, double angle_deg = 30.0, double tolerance_deg = 2.0);
}
