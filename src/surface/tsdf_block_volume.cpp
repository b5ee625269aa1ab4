/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include "tsdf_block_volume.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/surface/marching_cubes.h>  // pcl::edgeTable, pcl::triTable (Bourke's tables)

#include "../common/parallel_for.h"

#include <algorithm>
#include <cstdlib>

namespace pcl
{
  namespace detail
  {
    namespace
    {
      /** Cube corners in pcl::MarchingCubes' order, which its tables assume. */
      const int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
      /** The corners joined by each of the twelve cube edges. */
      const int kEdge[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

      int
      voxelIndex (int x, int y, int z)
      {
        return x + kBlockSide * (y + kBlockSide * z);
      }

      /** One block and its seven neighbours on the +x, +y, +z sides, for the cubes that cross into them. */
      struct BlockNeighbourhood
      {
        std::array<int, 8> index;  ///< block indices by (dx | dy << 1 | dz << 2), -1 when absent
      };

      /** What marching cubes finds in a run of blocks: its vertices, one per cube edge the zero set
        * crosses (keyed by the edge, at the position the first cube to reach it computes), in the order
        * the cubes first reach them, and its triangles over them. */
      class ZeroSetPiece
      {
        public:
          std::uint32_t
          vertex (std::uint64_t key, const Eigen::Vector3f& position)
          {
            const auto inserted = index_.emplace (key, static_cast<std::uint32_t> (keys.size ()));
            if (inserted.second)
            {
              keys.push_back (key);
              positions.push_back (position);
            }
            return inserted.first->second;
          }

          std::vector<std::uint64_t> keys;
          std::vector<Eigen::Vector3f> positions;
          std::vector<Eigen::Vector3i> triangles;

        private:
          std::unordered_map<std::uint64_t, std::uint32_t> index_;
      };

      /** Blocks extracted as one piece: small enough that the pieces keep every core busy. */
      constexpr std::size_t kBlocksPerPiece = 64;
    }

    std::uint64_t
    TsdfBlockVolume::key (const Eigen::Vector3i& block)
    {
      const std::uint64_t mask = (std::uint64_t (1) << 21) - 1;
      return (static_cast<std::uint64_t> (block.x ()) & mask) | ((static_cast<std::uint64_t> (block.y ()) & mask) << 21)
           | ((static_cast<std::uint64_t> (block.z ()) & mask) << 42);
    }

    std::size_t
    TsdfBlockVolume::bytesPerBlock ()
    {
      // The voxels, the block's coordinates and an unordered_map node with its bucket.
      return sizeof (TsdfBlock) + sizeof (Eigen::Vector3i) + 48;
    }

    void
    TsdfBlockVolume::reserveBlock (const Eigen::Vector3i& block)
    {
      if (!inRange (block))
        PCL_TENSOR_THROW (MemoryLimitException, "volumetric integration: the views span more than "
                          << kMaxBlockCoordinate << " blocks of " << kBlockSide << " voxels of " << voxel_size_
                          << " m from the origin; use larger voxels");
      const auto inserted = index_.emplace (key (block), static_cast<std::uint32_t> (keys_.size ()));
      if (!inserted.second)
        return;
      if (keys_.size () >= max_blocks_)
        PCL_TENSOR_THROW (MemoryLimitException, "volumetric integration: more than " << max_blocks_ << " voxel blocks ("
                          << max_blocks_ * bytesPerBlock () / (1 << 20) << " MiB) are needed at a voxel size of "
                          << voxel_size_ << " m; use larger voxels or raise the memory limit");
      keys_.push_back (block);
    }

    void
    TsdfBlockVolume::allocate ()
    {
      blocks_.assign (keys_.size (), TsdfBlock ());
    }

    const TsdfBlock*
    TsdfBlockVolume::find (const Eigen::Vector3i& block) const
    {
      const auto it = index_.find (key (block));
      return it == index_.end () || it->second >= blocks_.size () ? nullptr : &blocks_[it->second];
    }

    std::size_t
    TsdfBlockVolume::memoryBytes () const
    {
      return keys_.size () * bytesPerBlock () + index_.bucket_count () * sizeof (void*);
    }

    namespace
    {
      /** The block at index \a b and its seven neighbours on the +x, +y, +z sides. */
      BlockNeighbourhood
      neighbourhood (const TsdfBlockVolume& volume, std::size_t b)
      {
        const Eigen::Vector3i origin = volume.blockCoordinates (b);
        BlockNeighbourhood hood;
        hood.index[0] = static_cast<int> (b);
        for (int n = 1; n < 8; ++n)
        {
          const TsdfBlock* block = volume.find (origin + Eigen::Vector3i (n & 1, (n >> 1) & 1, (n >> 2) & 1));
          hood.index[n] = block == nullptr ? -1 : static_cast<int> (block - &volume.block (0));
        }
        return hood;
      }

      /** One cube of marching cubes: the block, voxel and signed distance at each of its corners. */
      struct Cube
      {
        float value[8];
        int block[8], voxel[8];
        int index = 0;  ///< the case of Bourke's tables: bit c set when corner c is inside
      };

      /** The cube whose lowest corner is voxel (x, y, z) of the block of \a hood; false when one of its
        * corners lies in no block or was never seen. */
      bool
      cubeAt (const TsdfBlockVolume& volume, const BlockNeighbourhood& hood, int x, int y, int z, Cube& cube)
      {
        cube.index = 0;
        for (int c = 0; c < 8; ++c)
        {
          const int px = x + kCorner[c][0], py = y + kCorner[c][1], pz = z + kCorner[c][2];
          cube.block[c] = hood.index[(px >> 3) | ((py >> 3) << 1) | ((pz >> 3) << 2)];
          if (cube.block[c] < 0)
            return false;
          cube.voxel[c] = voxelIndex (px & 7, py & 7, pz & 7);
          const TsdfVoxel& v = volume.block (static_cast<std::size_t> (cube.block[c]))[cube.voxel[c]];
          if (!(v.weight > 0.0f))
            return false;
          cube.value[c] = v.distance;
          if (cube.value[c] < 0.0f)
            cube.index |= 1 << c;
        }
        return true;
      }

      /** The vertex where the zero set crosses edge \a e of \a cube (lowest corner at \a voxel, in global
        * voxel coordinates), welded in \a piece: the edge is keyed by its lower corner (block and voxel)
        * and its axis, so the cubes around it share it. */
      std::uint32_t
      edgeVertex (const Cube& cube, int e, const Eigen::Vector3i& voxel, float voxel_size, ZeroSetPiece& piece)
      {
        const int a = kEdge[e][0], b = kEdge[e][1];
        int axis = 0;
        while (kCorner[a][axis] == kCorner[b][axis])
          ++axis;
        const int lower = kCorner[a][axis] < kCorner[b][axis] ? a : b;
        const std::uint64_t key = (static_cast<std::uint64_t> (cube.block[lower]) * kBlockVoxels
                                   + static_cast<std::uint64_t> (cube.voxel[lower])) * 3 + axis;
        const float t = cube.value[a] / (cube.value[a] - cube.value[b]);
        Eigen::Vector3f p;
        for (int k = 0; k < 3; ++k)
          p[k] = voxel_size * (static_cast<float> (voxel[k] + kCorner[a][k]) + t * static_cast<float> (kCorner[b][k] - kCorner[a][k]));
        return piece.vertex (key, p);
      }

      /** The triangles of \a cube (lowest corner at \a voxel) into \a piece. */
      void
      addCube (const Cube& cube, const Eigen::Vector3i& voxel, float voxel_size, ZeroSetPiece& piece)
      {
        std::uint32_t edge_vertex[12];
        for (int e = 0; e < 12; ++e)
          if (pcl::edgeTable[cube.index] & (1u << e))
            edge_vertex[e] = edgeVertex (cube, e, voxel, voxel_size, piece);
        for (int i = 0; pcl::triTable[cube.index][i] != -1; i += 3)
        {
          const Eigen::Vector3i tri (static_cast<int> (edge_vertex[pcl::triTable[cube.index][i]]),
                                     static_cast<int> (edge_vertex[pcl::triTable[cube.index][i + 1]]),
                                     static_cast<int> (edge_vertex[pcl::triTable[cube.index][i + 2]]));
          // A corner value of exactly 0 can weld two corners of a triangle into one vertex.
          if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2])
            piece.triangles.push_back (tri);
        }
      }

      /** Marching cubes over blocks [first, last) of \a volume (see extractZeroSet). */
      void
      extractBlocks (const TsdfBlockVolume& volume, std::size_t first, std::size_t last, ZeroSetPiece& piece)
      {
        const float s = static_cast<float> (volume.voxelSize ());
        Cube cube;
        for (std::size_t b = first; b < last; ++b)
        {
          const BlockNeighbourhood hood = neighbourhood (volume, b);
          const Eigen::Vector3i origin = volume.blockCoordinates (b) * kBlockSide;
          for (int z = 0; z < kBlockSide; ++z)
            for (int y = 0; y < kBlockSide; ++y)
              for (int x = 0; x < kBlockSide; ++x)
                if (cubeAt (volume, hood, x, y, z, cube) && pcl::edgeTable[cube.index] != 0)
                  addCube (cube, origin + Eigen::Vector3i (x, y, z), s, piece);
        }
      }
    }

    void
    extractZeroSet (const TsdfBlockVolume& volume, std::vector<Eigen::Vector3f>& vertices,
                    std::vector<Eigen::Vector3i>& triangles, unsigned threads)
    {
      vertices.clear ();
      triangles.clear ();
      std::vector<ZeroSetPiece> pieces ((volume.blockCount () + kBlocksPerPiece - 1) / kBlocksPerPiece);
      pcl::detail::parallelFor (pieces.size (), threads, [&] (std::size_t k) {
        extractBlocks (volume, k * kBlocksPerPiece, std::min (volume.blockCount (), (k + 1) * kBlocksPerPiece), pieces[k]);
      });
      // Welded piece by piece in block order: each vertex gets the index and the position of the first
      // cube, over all blocks in order, that reaches it, as one pass over the blocks would give it.
      std::unordered_map<std::uint64_t, std::uint32_t> welded;
      std::vector<std::uint32_t> index;
      for (auto& piece : pieces)
      {
        index.resize (piece.keys.size ());
        for (std::size_t i = 0; i < piece.keys.size (); ++i)
        {
          const auto inserted = welded.emplace (piece.keys[i], static_cast<std::uint32_t> (vertices.size ()));
          if (inserted.second)
            vertices.push_back (piece.positions[i]);
          index[i] = inserted.first->second;
        }
        for (const auto& t : piece.triangles)
          triangles.emplace_back (index[t[0]], index[t[1]], index[t[2]]);
        piece = ZeroSetPiece ();
      }
    }
  }
}
