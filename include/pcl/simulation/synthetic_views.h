/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>
#include <pcl/simulation/scanner_artifacts.h>
#include <pcl/simulation/view_set.h>
#include <pcl/simulation/zbuffer_range_renderer.h>

#include <cstdint>
#include <vector>

namespace pcl
{
  /** \brief How a set of synthetic range images is made from a model (Sections 6, 7.1 and 7.5).
    * \ingroup simulation
    */
  struct SyntheticViewParams
  {
    /** The camera. For an orthographic camera, ortho_extent is replaced by one that fits the model. */
    RangeCameraParams camera;
    /** The model's bounding sphere is fitted into the field of view with this margin (>= 1). */
    double margin = 1.05;
    /** Gaussian noise along the viewing direction, sigma in units of each view's d_res (Section 7.5: 1 to 4). */
    double noise_sigma_resolutions = 0.0;
    /** Seed of the std::mt19937 that draws the noise; the views are noised in order from one engine. */
    std::uint32_t seed = 2006;
    /** What a real scanner loses and adds (addScannerArtifacts()), applied before the noise and drawn
      * from an engine of its own, so that the noise is the same with and without them. Default: none. */
    ScannerArtifactParams artifacts;
    /** The model's up axis: the poles of the default view set, and the cameras' image up direction. */
    Eigen::Vector3d up = Eigen::Vector3d::UnitY ();
  };

  /** \brief One synthetic range image with its ground truth and resolution.
    * \ingroup simulation
    */
  struct SyntheticView
  {
    /** The range image in the sensor frame, and its pose into the model frame. */
    RenderedView view;
    /** d_res of the noise-free view: meshResolution() of its RangeScanTriangulation mesh M_i. */
    double resolution = 0.0;
  };

  /** \brief Render the model from sensors looking at its centre along \a directions, fitted to the view,
    * and add the requested noise.
    * \param[in] model the triangle mesh to view
    * \param[in] directions unit directions from the model's centre toward each sensor (e.g. makeDefaultViewDirections())
    * \param[in] params camera, margin, noise and seed
    * \return one view per direction, in order
    * \throw pcl::BadArgumentException on bad parameters (see ZBufferRangeRenderer, fittingDistance, noise)
    * \throw InvalidScanException when the model has no triangle or a view sees fewer than 3 points
    * \ingroup simulation
    */
  std::vector<SyntheticView>
  renderSyntheticViews (const ScanMesh& model, const ViewDirections& directions, const SyntheticViewParams& params);

  /** \brief Render the model from an explicit list of sensor poses (sensor frame -> model frame); the
    * camera is used as given (no fitting), and the noise is added as above.
    * \throw as the other overload
    * \ingroup simulation
    */
  std::vector<SyntheticView>
  renderSyntheticViews (const ScanMesh& model, const SensorPoses& poses, const SyntheticViewParams& params);
}
