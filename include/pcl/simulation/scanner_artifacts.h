/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/simulation/zbuffer_range_renderer.h>

#include <random>

namespace pcl
{
  /** \brief What real range scanners lose and add that a clean z-buffer does not: surfaces seen at
    * grazing angles drop out (the stripe spreads and too little light returns), dark or specular patches
    * leave holes, and dust or inter-reflections leave small stray specks in front of the surface. Each
    * is off at its default.
    * \ingroup simulation
    */
  struct ScannerArtifactParams
  {
    /** Points whose surface turns more than this from the line of sight (degrees, between the normal
      * and the ray) drop out, with a probability rising linearly to 1 at 90 degrees (90: none). */
    double dropout_start_deg = 90.0;
    /** Holes per view: discs of the image around random surface pixels, emptied. */
    int holes = 0;
    /** A hole's mean radius in pixels; each is drawn between half and one and a half times it. */
    double hole_radius_pixels = 4.0;
    /** Specks per view: a few neighbouring surface pixels moved together toward the sensor. */
    int specks = 0;
    /** Pixels per speck at most (each has 1 to this many, in one image row). */
    int speck_pixels = 3;
  };

  /** \brief A moderate setting of every artifact, for evaluations: dropout from 70 degrees, 4 holes of
    * 4 pixels and 20 specks of up to 3 pixels per view (of 400 x 400). */
  ScannerArtifactParams
  scannerLikeArtifacts ();

  /** \brief Apply \a params to \a view (an organized rendering, before any noise), drawing from \a rng.
    * Normals are taken from the grid's neighbours, so that dropout follows the surface as the sensor
    * saw it. A speck lies on the lines of sight of the pixels it replaces, 5% to 50% of their depth nearer.
    * \throw pcl::BadArgumentException when a parameter is out of range (dropout_start_deg outside
    * [0, 90], negative counts or radius, speck_pixels < 1) or the view's cloud is not organized
    */
  void
  addScannerArtifacts (RenderedView& view, const ScannerArtifactParams& params, std::mt19937& rng);
}
