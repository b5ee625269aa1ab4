/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 *
 * Private to the library: the sparse voxel volume of ScanVolumetricIntegration and its marching cubes.
 */
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace pcl
{
  namespace detail
  {
    /** Voxels per block side; blocks are 8^3 voxels. */
    constexpr int kBlockSide = 8;
    constexpr int kBlockVoxels = kBlockSide * kBlockSide * kBlockSide;

    /** One voxel: the weighted mean signed distance and the sum of the weights. */
    struct TsdfVoxel
    {
      float distance = 0.0f;
      float weight = 0.0f;
    };

    /** 8^3 voxels, x fastest. */
    using TsdfBlock = std::array<TsdfVoxel, kBlockVoxels>;

    /** A sparse grid of voxel blocks indexed by integer block coordinates. Voxel (i, j, k) of the
      * volume sits at (i, j, k) * voxel_size in the world frame, in block floor((i, j, k) / 8). */
    class TsdfBlockVolume
    {
      public:
        /** Blocks are indexed by 21-bit signed coordinates; larger volumes are refused. */
        static constexpr int kMaxBlockCoordinate = (1 << 20) - 1;

        TsdfBlockVolume (double voxel_size, std::size_t max_blocks) : voxel_size_ (voxel_size), max_blocks_ (max_blocks) {}

        /** Register the block (no voxel memory yet); throws MemoryLimitException past max_blocks. */
        void reserveBlock (const Eigen::Vector3i& block);
        /** Allocate the voxels of every registered block, all unseen. */
        void allocate ();

        /** The block at \a block coordinates, or nullptr. */
        const TsdfBlock* find (const Eigen::Vector3i& block) const;

        std::size_t blockCount () const { return keys_.size (); }
        const Eigen::Vector3i& blockCoordinates (std::size_t i) const { return keys_[i]; }
        TsdfBlock& block (std::size_t i) { return blocks_[i]; }
        const TsdfBlock& block (std::size_t i) const { return blocks_[i]; }
        double voxelSize () const { return voxel_size_; }
        /** Bytes of the voxels and of the index. */
        std::size_t memoryBytes () const;
        /** Estimated bytes per block: the voxels and one index entry. */
        static std::size_t bytesPerBlock ();

        /** True when \a block's coordinates are within kMaxBlockCoordinate (reserveBlock() refuses others). */
        static bool inRange (const Eigen::Vector3i& block) { return block.cwiseAbs ().maxCoeff () <= kMaxBlockCoordinate; }

        /** The index key of a block: one-to-one for coordinates within kMaxBlockCoordinate. */
        static std::uint64_t key (const Eigen::Vector3i& block);

      private:

        double voxel_size_;
        std::size_t max_blocks_;
        std::unordered_map<std::uint64_t, std::uint32_t> index_;
        std::vector<Eigen::Vector3i> keys_;
        std::vector<TsdfBlock> blocks_;
    };

    /** Marching cubes over the volume (Lorensen & Cline with Bourke's tables, as pcl::MarchingCubes):
      * the zero set of the signed distance in cubes whose eight corners all have weight > 0, with
      * vertices shared between cubes. Triangles are wound so that their normals point toward positive
      * distance (the sensors' side: out of the object). Runs of blocks are processed on \a threads
      * threads (0: every core) and welded in block order: the mesh is the same on any number. */
    void
    extractZeroSet (const TsdfBlockVolume& volume, std::vector<Eigen::Vector3f>& vertices,
                    std::vector<Eigen::Vector3i>& triangles, unsigned threads = 1);
  }
}
