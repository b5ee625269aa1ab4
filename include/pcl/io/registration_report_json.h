/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/registration/multiview_tensor_registration.h>
#include <pcl/registration/tensor_registration.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <nlohmann/json.hpp>

#include <string>

namespace pcl
{
  namespace io
  {
    /** \brief A JSON report: keys stay in the order they were written, so reports read top-down. */
    using JsonReport = nlohmann::ordered_json;

    /** \brief A 4x4 matrix as 16 numbers, row-major. Every float is written exactly (as its double). */
    JsonReport
    toJson (const Eigen::Matrix4f& m);
    JsonReport
    toJson (const Eigen::Matrix4d& m);

    /** \brief What one pairwise registration did (pcl_tensor_register --json, the Python report):
      * status, transform, hypotheses, tensors, failures per verification stage and timings.
      */
    JsonReport
    toJson (const pcl::registration::TensorRegistrationReport& report);

    /** \brief One view of a multiview run: file, status, reference view, pose (row-major), and why not. */
    JsonReport
    toJson (const pcl::registration::ViewRegistrationStatus& view);

    /** \brief A multiview run (pcl_tensor_model --json): every view, the global step and the timings. */
    JsonReport
    toJson (const pcl::registration::MultiviewRegistrationResult& result);

    /** \brief The volume volumetric integration used. */
    JsonReport
    toJson (const pcl::VolumetricIntegrationReport& report);

    /** \brief \a report on one line. Strings are escaped, and bytes that are not UTF-8 (a file name in
      * another encoding) are written as U+FFFD instead of throwing: a report is never lost to a name.
      */
    std::string
    dumpJson (const JsonReport& report);
  }
}
