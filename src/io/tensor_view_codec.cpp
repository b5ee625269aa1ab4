/*
 * pcl_tensor: the payloads of the cache entries, a view's meshes and its tensors, as bytes
 * (internal; TensorViewCache).
 */
#include "tensor_view_codec.h"
#include "byte_codec.h"

#include <memory>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      namespace
      {
        constexpr std::size_t kPointNormalBytes = 7 * sizeof (float);
        constexpr std::size_t kTensorFixedBytes = 14 * sizeof (float) + 4 * sizeof (std::int32_t);

        template <typename Vector> void
        putVector (ByteWriter& out, const Vector& v)
        {
          for (Eigen::Index i = 0; i < v.size (); ++i)
            out.put (v.data ()[i]);
        }

        template <typename Vector> void
        getVector (ByteReader& in, Vector& v)
        {
          for (Eigen::Index i = 0; i < v.size (); ++i)
            v.data ()[i] = in.template get<typename Vector::Scalar> ();
        }

        /** Everything of a cloud but its points: header, organization, density and sensor. */
        template <typename PointT> void
        putCloudMeta (ByteWriter& out, const pcl::PointCloud<PointT>& cloud)
        {
          out.put (cloud.header.seq).put (cloud.header.stamp).putString (cloud.header.frame_id);
          out.put (cloud.width).put (cloud.height).put (static_cast<std::uint8_t> (cloud.is_dense));
          putVector (out, cloud.sensor_origin_);
          putVector (out, cloud.sensor_orientation_.coeffs ());
        }

        template <typename PointT> void
        getCloudMeta (ByteReader& in, pcl::PointCloud<PointT>& cloud)
        {
          cloud.header.seq = in.get<std::uint32_t> ();
          cloud.header.stamp = in.get<std::uint64_t> ();
          cloud.header.frame_id = in.getString ();
          cloud.width = in.get<std::uint32_t> ();
          cloud.height = in.get<std::uint32_t> ();
          cloud.is_dense = in.get<std::uint8_t> () != 0;
          getVector (in, cloud.sensor_origin_);
          getVector (in, cloud.sensor_orientation_.coeffs ());
        }

        /** The point count, after checking that \a element_size bytes of each fit and that the
          * organization read by getCloudMeta() accounts for them. */
        template <typename PointT> bool
        getPointCount (ByteReader& in, const pcl::PointCloud<PointT>& cloud, std::size_t element_size, std::size_t& n)
        {
          const auto count = in.get<std::uint64_t> ();
          n = static_cast<std::size_t> (count);
          return in.fits (count, element_size) && count == std::uint64_t (cloud.width) * cloud.height;
        }

        void
        putMesh (ByteWriter& out, const ScanMesh& mesh)
        {
          out.put (static_cast<std::uint32_t> (mesh.viewpoint.model));
          putVector (out, mesh.viewpoint.sensor_pose.matrix ());
          putCloudMeta (out, *mesh.cloud);
          out.put<std::uint64_t> (mesh.cloud->size ());
          for (const auto& p : *mesh.cloud)
            out.put (p.x).put (p.y).put (p.z).put (p.normal_x).put (p.normal_y).put (p.normal_z).put (p.curvature);
          out.put<std::uint64_t> (mesh.polygons.size ());
          for (const auto& polygon : mesh.polygons)
          {
            out.put<std::uint64_t> (polygon.vertices.size ());
            for (const auto v : polygon.vertices)
              out.put (static_cast<std::uint32_t> (v));
          }
        }

        bool
        getViewpoint (ByteReader& in, ScanViewpoint& viewpoint)
        {
          const auto model = in.get<std::uint32_t> ();
          if (model > static_cast<std::uint32_t> (ScanViewpoint::Model::pushbroom))
            return false;
          viewpoint.model = static_cast<ScanViewpoint::Model> (model);
          getVector (in, viewpoint.sensor_pose.matrix ());
          return in.ok ();
        }

        bool
        getPolygons (ByteReader& in, std::size_t vertices, std::vector<pcl::Vertices>& polygons)
        {
          const auto count = in.get<std::uint64_t> ();
          if (!in.fits (count, sizeof (std::uint64_t)))
            return false;
          polygons.resize (count);
          for (auto& polygon : polygons)
          {
            const auto size = in.get<std::uint64_t> ();
            if (!in.fits (size, sizeof (std::uint32_t)))
              return false;
            polygon.vertices.resize (size);
            for (auto& v : polygon.vertices)
            {
              const auto index = in.get<std::uint32_t> ();
              if (index >= vertices)
                return false;
              v = static_cast<pcl::index_t> (index);
            }
          }
          return in.ok ();
        }

        bool
        getMesh (ByteReader& in, ScanMesh& mesh)
        {
          if (!getViewpoint (in, mesh.viewpoint))
            return false;
          auto& cloud = *mesh.cloud;
          getCloudMeta (in, cloud);
          std::size_t n = 0;
          if (!getPointCount (in, cloud, kPointNormalBytes, n))
            return false;
          cloud.points.resize (n);
          for (auto& p : cloud)
          {
            p.x = in.get<float> (); p.y = in.get<float> (); p.z = in.get<float> ();
            p.normal_x = in.get<float> (); p.normal_y = in.get<float> (); p.normal_z = in.get<float> ();
            p.curvature = in.get<float> ();
          }
          return getPolygons (in, n, mesh.polygons);
        }

        void
        putTensor (ByteWriter& out, const pcl::TensorDescriptor& t)
        {
          out.put (t.x).put (t.y).put (t.z);
          for (const float r : t.rf)
            out.put (r);
          out.put (t.theta_d).put (t.bin_size).put (t.vertex_a).put (t.vertex_b).put (t.grid_size).put (t.order_ambiguous);
          out.put<std::uint64_t> (t.bin_index.size ());
          for (const auto i : t.bin_index)
            out.put (i);
          out.put<std::uint64_t> (t.bin_area.size ());
          for (const auto a : t.bin_area)
            out.put (a);
        }

        template <typename T> bool
        getArray (ByteReader& in, std::vector<T>& values)
        {
          const auto count = in.get<std::uint64_t> ();
          if (!in.fits (count, sizeof (T)))
            return false;
          values.resize (count);
          for (auto& v : values)
            v = in.get<T> ();
          return true;
        }

        bool
        getTensor (ByteReader& in, pcl::TensorDescriptor& t)
        {
          t.x = in.get<float> (); t.y = in.get<float> (); t.z = in.get<float> ();
          for (float& r : t.rf)
            r = in.get<float> ();
          t.theta_d = in.get<float> ();
          t.bin_size = in.get<float> ();
          t.vertex_a = in.get<std::int32_t> ();
          t.vertex_b = in.get<std::int32_t> ();
          t.grid_size = in.get<std::int32_t> ();
          t.order_ambiguous = in.get<std::uint32_t> ();
          return getArray (in, t.bin_index) && getArray (in, t.bin_area);
        }
      }

      std::string
      encodeViewPayload (const pcl::registration::TensorView& view, const Eigen::Vector3d& extents)
      {
        ByteWriter out;
        putVector (out, view.origin);
        putVector (out, extents);
        out.put (view.scan->resolution).put (view.scan->noise);
        putMesh (out, view.scan->fine);
        putMesh (out, view.scan->reduced);
        return std::move (out.bytes ());
      }

      bool
      decodeViewHead (std::string_view payload, Eigen::Vector3d& origin, Eigen::Vector3d& extents)
      {
        ByteReader in (payload);
        getVector (in, origin);
        getVector (in, extents);
        return in.ok ();
      }

      bool
      decodeViewPayload (std::string_view payload, pcl::registration::TensorView& view, Eigen::Vector3d& extents)
      {
        ByteReader in (payload);
        getVector (in, view.origin);
        getVector (in, extents);
        auto scan = std::make_shared<PreparedScan> ();
        scan->resolution = in.get<double> ();
        scan->noise = in.get<double> ();
        if (!getMesh (in, scan->fine) || !getMesh (in, scan->reduced) || !in.atEnd ())
          return false;
        view.scan = scan;
        return true;
      }

      std::string
      encodeTensorPayload (const ObjectDimensions& dims, std::uint64_t tensor_hash,
                           const pcl::PointCloud<pcl::TensorDescriptor>& tensors)
      {
        ByteWriter out;
        putVector (out, dims.D);
        out.put (tensor_hash);
        putCloudMeta (out, tensors);
        out.put<std::uint64_t> (tensors.size ());
        for (const auto& t : tensors)
          putTensor (out, t);
        return std::move (out.bytes ());
      }

      bool
      decodeTensorHead (std::string_view payload, ObjectDimensions& dims, std::uint64_t& tensor_hash)
      {
        ByteReader in (payload);
        getVector (in, dims.D);
        tensor_hash = in.get<std::uint64_t> ();
        return in.ok ();
      }

      bool
      decodeTensorPayload (std::string_view payload, pcl::PointCloud<pcl::TensorDescriptor>& tensors)
      {
        ByteReader in (payload.substr (std::min (payload.size (), TENSOR_PAYLOAD_HEAD_SIZE)));
        getCloudMeta (in, tensors);
        std::size_t n = 0;
        // Each tensor holds at least its fixed fields and the two vector lengths.
        if (!getPointCount (in, tensors, kTensorFixedBytes + 2 * sizeof (std::uint64_t), n))
          return false;
        tensors.points.resize (n);
        for (auto& t : tensors)
          if (!getTensor (in, t))
            return false;
        return in.ok () && in.atEnd ();
      }
    }
  }
}
