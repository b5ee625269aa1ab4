/*
 * pcl_tensor: a pairwise registration report as cache bytes (internal; TensorViewCache's pair entries).
 */
#pragma once

#include <pcl/registration/tensor_registration_report.h>

#include <string>
#include <string_view>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      /** \brief Every field of \a report, little-endian (ByteWriter). */
      std::string
      encodeReportPayload (const pcl::registration::TensorRegistrationReport& report);

      /** \brief What encodeReportPayload() wrote; false on bytes that do not decode (nothing trusted). */
      bool
      decodeReportPayload (std::string_view payload, pcl::registration::TensorRegistrationReport& report);
    }
  }
}
