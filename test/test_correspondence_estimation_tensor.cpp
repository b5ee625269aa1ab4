#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/transforms.h>
#include <pcl/features/tensor.h>
#include <pcl/registration/correspondence_estimation_tensor.h>
#include <pcl/simulation/example_object.h>

namespace
{
  using TensorCloud = pcl::PointCloud<pcl::TensorDescriptor>;

  /** Tensors of the (closed) example object, moved by \a motion. */
  TensorCloud::Ptr
  patchTensors (const Eigen::Affine3f& motion)
  {
    pcl::ExampleObjectParams params;
    params.subdivisions = 3;
    const pcl::ScanMesh object = pcl::makeExampleObject (params);
    pcl::PointCloud<pcl::PointNormal>::Ptr cloud (new pcl::PointCloud<pcl::PointNormal>);
    pcl::transformPointCloudWithNormals (*object.cloud, *cloud, motion);
    pcl::ObjectDimensions dims;
    dims.D = pcl::principalExtents (*object.cloud);
    pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal> estimation;
    estimation.setInputCloud (cloud);
    estimation.setInputNormals (cloud);
    estimation.setPolygons (object.polygons);
    estimation.setObjectDimensions (dims);
    TensorCloud::Ptr tensors (new TensorCloud);
    estimation.computeOrThrow (*tensors);
    return tensors;
  }
}

TEST (CorrespondenceEstimationTensor, EveryTensorFindsItsMovedTwinWithCorrelationOne)
{
  std::mt19937 rng (11);
  const Eigen::Affine3f motion (pcl_tensor_test::randomRigidTransform (rng, 0.2).matrix ().cast<float> ());
  const auto model = patchTensors (motion);
  const auto scene = patchTensors (Eigen::Affine3f::Identity ());
  ASSERT_EQ (model->size (), scene->size ());

  pcl::registration::CorrespondenceEstimationTensor estimation;
  estimation.setInputSource (scene);
  estimation.setInputTarget (model);
  pcl::Correspondences correspondences;
  estimation.determineCorrespondences (correspondences);
  // The same pairs in the same order: scene tensor i's twin is model tensor i.
  std::vector<float> best (scene->size (), -2.0f);
  std::vector<int> best_model (scene->size (), -1);
  for (const auto& m : estimation.getMatches ())
    if (m.correlation > best[m.scene])
    {
      best[m.scene] = m.correlation;
      best_model[m.scene] = m.model;
    }
  std::size_t twins = 0;
  for (std::size_t s = 0; s < scene->size (); ++s)
    twins += (best_model[s] == static_cast<int> (s) && best[s] > 0.999f);
  EXPECT_GE (twins, scene->size () * 99 / 100) << "of " << scene->size ();
  EXPECT_LT (estimation.getComparisons (), scene->size () * model->size ()) << "the theta_d index prunes comparisons";
}

TEST (CorrespondenceEstimationTensor, ThresholdsAndOrdersHold)
{
  const auto tensors = patchTensors (Eigen::Affine3f::Identity ());
  pcl::registration::CorrespondenceEstimationTensor estimation;
  estimation.setInputSource (tensors);
  estimation.setInputTarget (tensors);
  estimation.setOverlapThreshold (0.6f);
  estimation.setCorrelationThreshold (0.7f);
  pcl::Correspondences best_first;
  estimation.determineCorrespondences (best_first);
  const auto matches = estimation.getMatches ();
  ASSERT_EQ (matches.size (), best_first.size ());
  for (std::size_t k = 0; k < matches.size (); ++k)
  {
    EXPECT_GE (matches[k].overlap_ratio, 0.6f);
    EXPECT_GE (matches[k].correlation, 0.7f);
    EXPECT_FLOAT_EQ (best_first[k].distance, 1.0f - matches[k].correlation);
    if (k > 0)
    {
      EXPECT_GE (matches[k - 1].correlation, matches[k].correlation);
    }
  }
  estimation.setOrder (pcl::registration::TensorMatchOrder::SCENE_ORDER);
  pcl::Correspondences scene_order;
  estimation.determineCorrespondences (scene_order);
  EXPECT_EQ (scene_order.size (), best_first.size ());
  for (std::size_t k = 1; k < scene_order.size (); ++k)
    EXPECT_LE (scene_order[k - 1].index_query, scene_order[k].index_query);

  // Without the index every pair is compared, and the index loses no match at the same thresholds.
  const std::size_t indexed = estimation.getComparisons ();
  estimation.setUseThetaIndex (false);
  pcl::Correspondences exhaustive;
  estimation.determineCorrespondences (exhaustive);
  EXPECT_GT (estimation.getComparisons (), indexed);
  EXPECT_GE (exhaustive.size (), scene_order.size ());
}

TEST (CorrespondenceEstimationTensor, BadInputThrows)
{
  pcl::registration::CorrespondenceEstimationTensor estimation;
  pcl::Correspondences c;
  EXPECT_THROW (estimation.determineCorrespondences (c), pcl::BadArgumentException);
  EXPECT_THROW (estimation.setOverlapThreshold (1.5f), pcl::BadArgumentException);
  EXPECT_THROW (estimation.setCorrelationThreshold (-2.0f), pcl::BadArgumentException);
  EXPECT_THROW (estimation.setThetaBinWidth (0.0), pcl::BadArgumentException);
  auto a = patchTensors (Eigen::Affine3f::Identity ());
  TensorCloud::Ptr b (new TensorCloud (*a));
  for (auto& t : *b)
    t.grid_size = 15;
  estimation.setInputSource (a);
  estimation.setInputTarget (b);
  EXPECT_THROW (estimation.determineCorrespondences (c), pcl::BadArgumentException);
}
