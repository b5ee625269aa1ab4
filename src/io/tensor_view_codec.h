/*
 * pcl_tensor: the payloads of the cache entries, a view's meshes and its tensors, as bytes
 * (internal; TensorViewCache). The decoders return false on bytes that do not decode, and then leave
 * their outputs in an unspecified state: callers decode into scratch objects.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/features/tensor_descriptor.h>
#include <pcl/registration/tensor_view.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      /** \brief Bytes at the start of a meshes payload that hold the origin and the extents. */
      constexpr std::size_t VIEW_PAYLOAD_HEAD_SIZE = 6 * sizeof (double);
      /** \brief Bytes at the start of a tensors payload that hold D and the tensor hash. */
      constexpr std::size_t TENSOR_PAYLOAD_HEAD_SIZE = 3 * sizeof (double) + sizeof (std::uint64_t);

      /** \brief A view's origin, \a extents, d_res, noise and both meshes. */
      std::string
      encodeViewPayload (const pcl::registration::TensorView& view, const Eigen::Vector3d& extents);

      /** \brief The origin and extents alone (\a payload may be just its first VIEW_PAYLOAD_HEAD_SIZE bytes). */
      bool
      decodeViewHead (std::string_view payload, Eigen::Vector3d& origin, Eigen::Vector3d& extents);

      /** \brief The whole view: origin and meshes into \a view (tensors untouched), and the extents. */
      bool
      decodeViewPayload (std::string_view payload, pcl::registration::TensorView& view, Eigen::Vector3d& extents);

      /** \brief D, the tensor hash and every field of every tensor. */
      std::string
      encodeTensorPayload (const ObjectDimensions& dims, std::uint64_t tensor_hash,
                           const pcl::PointCloud<pcl::TensorDescriptor>& tensors);

      /** \brief D and the tensor hash alone. */
      bool
      decodeTensorHead (std::string_view payload, ObjectDimensions& dims, std::uint64_t& tensor_hash);

      /** \brief The tensors (after the head). */
      bool
      decodeTensorPayload (std::string_view payload, pcl::PointCloud<pcl::TensorDescriptor>& tensors);
    }
  }
}
