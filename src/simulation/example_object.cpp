/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/simulation/example_object.h>
#include <pcl/common/tensor_exceptions.h>

#include <map>
#include <random>

namespace pcl
{
  namespace
  {
    struct Icosphere
    {
      std::vector<Eigen::Vector3d> vertices;
      std::vector<std::array<std::uint32_t, 3>> faces;
    };

    Icosphere
    icosahedron ()
    {
      const double t = (1.0 + std::sqrt (5.0)) / 2.0;
      Icosphere s;
      s.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
      for (auto& v : s.vertices)
        v.normalize ();
      s.faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
      return s;
    }

    /** Split every triangle into four, projecting the new vertices onto the unit sphere. */
    void
    subdivide (Icosphere& s)
    {
      std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
      auto midpoint = [&] (std::uint32_t a, std::uint32_t b) {
        const auto key = std::minmax (a, b);
        const auto it = midpoints.find (key);
        if (it != midpoints.end ())
          return it->second;
        s.vertices.push_back ((s.vertices[a] + s.vertices[b]).normalized ());
        const auto idx = static_cast<std::uint32_t> (s.vertices.size () - 1);
        midpoints.emplace (key, idx);
        return idx;
      };
      std::vector<std::array<std::uint32_t, 3>> faces;
      faces.reserve (s.faces.size () * 4);
      for (const auto& f : s.faces)
      {
        const auto ab = midpoint (f[0], f[1]), bc = midpoint (f[1], f[2]), ca = midpoint (f[2], f[0]);
        faces.push_back ({f[0], ab, ca});
        faces.push_back ({f[1], bc, ab});
        faces.push_back ({f[2], ca, bc});
        faces.push_back ({ab, bc, ca});
      }
      s.faces.swap (faces);
    }

    struct Bump
    {
      Eigen::Vector3d direction;
      double height;  // relative to the radius; negative for a dent
      double width;   // angular width, radians
    };

    /** Radial displacement on the unit sphere: a star-shaped surface, so it never self-intersects. */
    double
    radius (const Eigen::Vector3d& u, const std::vector<Bump>& bumps)
    {
      double r = 1.0;
      for (const auto& b : bumps)
      {
        const double angle = std::acos (std::clamp (u.dot (b.direction), -1.0, 1.0));
        r += b.height * std::exp (-0.5 * (angle * angle) / (b.width * b.width));
      }
      return r;
    }
  }

  ScanMesh
  makeExampleObject (const ExampleObjectParams& params)
  {
    if (params.subdivisions < 0 || params.subdivisions > 8)
      PCL_TENSOR_THROW (BadArgumentException, "example object subdivisions must be in [0, 8], got " << params.subdivisions);
    if (!(params.size > 0.0))
      PCL_TENSOR_THROW (BadArgumentException, "example object size must be positive, got " << params.size);

    std::mt19937 rng (params.seed);
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> uniform (0.0, 1.0);
    std::vector<Bump> bumps;
    for (int i = 0; i < params.bumps; ++i)
    {
      // One draw per statement: a constructor's arguments are evaluated in an unspecified order (gcc
      // right to left, clang left to right), which made the object depend on the compiler. This is
      // gcc's order, which every figure so far was measured with.
      const double dz = gauss (rng), dy = gauss (rng), dx = gauss (rng);
      const Eigen::Vector3d d (dx, dy, dz);
      // Alternate bumps and dents so that the surface has concavities as well as protrusions.
      const double sign = (i % 3 == 2) ? -1.0 : 1.0;
      bumps.push_back ({d.normalized (), sign * (0.12 + 0.2 * uniform (rng)), 0.18 + 0.25 * uniform (rng)});
    }

    Icosphere s = icosahedron ();
    for (int k = 0; k < params.subdivisions; ++k)
      subdivide (s);

    // Unequal semi-axes break the sphere's symmetry before any bump is added.
    const Eigen::Vector3d axes = Eigen::Vector3d (1.0, 0.72, 0.55) * (params.size / 2.0);
    ScanMesh mesh;
    mesh.cloud->resize (s.vertices.size ());
    for (std::size_t i = 0; i < s.vertices.size (); ++i)
    {
      const Eigen::Vector3d p = axes.cwiseProduct (s.vertices[i] * radius (s.vertices[i], bumps));
      (*mesh.cloud)[i].getVector3fMap () = p.cast<float> ();
    }
    mesh.polygons.resize (s.faces.size ());
    std::vector<Eigen::Vector3d> normals (s.vertices.size (), Eigen::Vector3d::Zero ());
    for (std::size_t f = 0; f < s.faces.size (); ++f)
    {
      const auto& t = s.faces[f];
      mesh.polygons[f].vertices = {static_cast<pcl::index_t> (t[0]), static_cast<pcl::index_t> (t[1]),
                                    static_cast<pcl::index_t> (t[2])};
      const Eigen::Vector3d a = (*mesh.cloud)[t[0]].getVector3fMap ().cast<double> ();
      const Eigen::Vector3d b = (*mesh.cloud)[t[1]].getVector3fMap ().cast<double> ();
      const Eigen::Vector3d c = (*mesh.cloud)[t[2]].getVector3fMap ().cast<double> ();
      const Eigen::Vector3d n = (b - a).cross (c - a);  // area-weighted, outward (icosahedron winding)
      for (const auto v : t)
        normals[v] += n;
    }
    for (std::size_t i = 0; i < normals.size (); ++i)
      (*mesh.cloud)[i].getNormalVector3fMap () = normals[i].normalized ().cast<float> ();
    mesh.cloud->width = static_cast<std::uint32_t> (mesh.cloud->size ());
    mesh.cloud->height = 1;
    mesh.cloud->is_dense = true;
    return mesh;
  }
}
