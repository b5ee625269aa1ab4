#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/registration/multiview_tensor_registration.h>
#include <pcl/registration/registration_error.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/synthetic_views.h>
#include <pcl/simulation/view_set.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <functional>
#include <limits>

namespace
{
  using namespace pcl::registration;

  /** A turntable: \a count views 30 degrees apart of \a object, at 300 x 300 (about 25,000 points each). */
  std::vector<pcl::SyntheticView>
  ringViews (const pcl::ScanMesh& object, int count)
  {
    pcl::SyntheticViewParams params;
    params.camera.width = params.camera.height = 300;
    return pcl::renderSyntheticViews (object, pcl::makeRingViewDirections (count, 30.0), params);
  }

  const std::vector<pcl::SyntheticView>&
  exampleRing ()
  {
    static const std::vector<pcl::SyntheticView> views = ringViews (pcl::makeExampleObject (), 12);
    return views;
  }

  MultiviewInput
  inputOf (const pcl::SyntheticView& view, const std::string& name)
  {
    return {name, view.view.cloud, view.view.viewpoint, nullptr};
  }

  /** The error of view \a i's estimated pose, with the estimate's frame put on the ground truth by
    * the reference view's true pose. */
  pcl::RegistrationError
  poseError (const MultiviewRegistrationResult& result, const Eigen::Affine3d& estimate,
             const Eigen::Affine3d& reference_truth, const Eigen::Affine3d& truth)
  {
    return pcl::registrationError (reference_truth * estimate, truth, result.resolution);
  }

  /** The centroid of view \a v's fine points under two poses, apart in d_res: independent of where
    * the sensor frame's origin is (0.3 m from the object here, which magnifies Eq. 12). */
  double
  centroidError (const ViewRegistrationStatus& v, const Eigen::Affine3d& a, const Eigen::Affine3d& b, double resolution)
  {
    Eigen::Vector3d c = Eigen::Vector3d::Zero ();
    for (const auto& p : *v.prepared->fine.cloud)
      c += p.getVector3fMap ().cast<double> ();
    c /= static_cast<double> (v.prepared->fine.cloud->size ());
    return (a * c - b * c).norm () / resolution;
  }
}

TEST (MultiviewTensorRegistration, TurntableRingIsRegisteredWithLoopClosure)
{
  const auto& views = exampleRing ();
  std::vector<MultiviewInput> inputs;
  for (std::size_t i = 0; i < views.size (); ++i)
    inputs.push_back (inputOf (views[i], "view" + std::to_string (i)));
  MultiviewRegistrationParams params;
  params.loop = true;
  MultiviewTensorRegistration registration;
  registration.setParams (params);
  std::vector<std::size_t> global_steps;
  registration.setProgressCallback ([&] (MultiviewStage stage, std::size_t done, std::size_t total) {
    EXPECT_LE (done, total);
    if (stage == MultiviewStage::GLOBAL)
      global_steps.push_back (done);
  });
  const MultiviewRegistrationResult result = registration.compute (inputs);

  ASSERT_EQ (result.registeredCount (), views.size ());
  EXPECT_EQ (result.reference, 0);
  EXPECT_TRUE (std::count (result.pairs.begin (), result.pairs.end (), std::make_pair (0, 11)) == 1)
      << "the loop pair (first, last) is missing from the global step";
  EXPECT_FALSE (global_steps.empty ());
  EXPECT_GT (result.global.iterations, 0);
  EXPECT_LE (result.global.rms_after, result.global.rms_before);
  for (std::size_t i = 0; i < views.size (); ++i)
  {
    const auto& v = result.views[i];
    EXPECT_TRUE (v.error.empty ());
    EXPECT_EQ (v.globally_refused, 0u) << v.name << ": the true pose was refused by global verification";
    EXPECT_LE (v.global_excess, params.global_verification.tolerance);
    const auto error = poseError (result, v.pose, views[0].view.pose, views[i].view.pose);
    const double centroid = centroidError (v, views[0].view.pose * v.pose, views[i].view.pose, result.resolution);
    std::cout << v.name << ": rotation error " << error.rotation_deg << " deg, centroid error " << centroid
              << " d_res, pose translation error " << error.translation_resolutions << " d_res" << std::endl;
    EXPECT_LT (error.rotation_deg, 0.05) << v.name;
    EXPECT_LT (centroid, 0.1) << v.name;
    EXPECT_LT (error.translation_resolutions, 0.5) << v.name;
  }
  EXPECT_GT (result.timings.total_ms, 0.0);
}

TEST (MultiviewTensorRegistration, ViewOfAnotherObjectIsLeftOut)
{
  const auto& views = exampleRing ();
  // Another object: a random height field (terrain) of the views' size and sampling.
  pcl::PointCloud<pcl::PointXYZ>::Ptr terrain (
      new pcl::PointCloud<pcl::PointXYZ> (pcl_tensor_test::makeHeightField (7, 150, 150, 0.001, 0.0)));
  // Four neighbours on the ring, with a view of another object after the second.
  const std::vector<MultiviewInput> inputs{inputOf (views[0], "a"), inputOf (views[1], "b"),
                                           MultiviewInput{"other", terrain, pcl::ScanViewpoint::fromPositiveZ (), nullptr},
                                           inputOf (views[2], "c"), inputOf (views[3], "d")};
  for (const auto search : {pcl::registration::ViewSearch::RANKED, pcl::registration::ViewSearch::ORDERED})
  {
  MultiviewTensorRegistration registration;
  MultiviewRegistrationParams params;
  params.search = search;
  registration.setParams (params);
  const MultiviewRegistrationResult result = registration.compute (inputs);
  SCOPED_TRACE (search == pcl::registration::ViewSearch::RANKED ? "ranked" : "ordered");

  EXPECT_FALSE (result.views[2].registered) << "a view of another object was registered";
  EXPECT_EQ (result.views[2].component, -1);
  EXPECT_TRUE (result.views[2].error.empty ()) << "the view was usable: verification must refuse it, not its input";
  if (search == pcl::registration::ViewSearch::ORDERED)
    EXPECT_EQ (result.views[2].references_tried, 4u) << "it is tried against every registered view";
  else  // every pair with it on the quick first pass, and its two best with every hypothesis
    EXPECT_EQ (result.views[2].references_tried, 6u);
  EXPECT_EQ (result.registeredCount (), 4u);
  EXPECT_EQ (result.components, 1);
  for (const std::size_t i : {0, 1, 3, 4})
  {
    const std::size_t ring = i < 2 ? i : i - 1;
    ASSERT_TRUE (result.views[i].registered) << result.views[i].name;
    const auto error = poseError (result, result.views[i].pose, views[0].view.pose, views[ring].view.pose);
    EXPECT_LT (error.rotation_deg, 0.05) << result.views[i].name;
  }
  for (const auto& p : result.pairs)
    EXPECT_TRUE (p.first != 2 && p.second != 2) << "the global step used the refused view: (" << p.first << ", " << p.second << ")";
  }
}

TEST (MultiviewTensorRegistration, ExplicitPairsAreTheOnlyReferences)
{
  const auto& views = exampleRing ();
  // Given in an order where view 2 comes before its only partner (view 1): it is registered on the
  // second pass, once view 1 is.
  const std::vector<MultiviewInput> inputs{inputOf (views[0], "v0"), inputOf (views[2], "v2"), inputOf (views[1], "v1")};
  MultiviewTensorRegistration registration;
  registration.setPairs ({{0, 2}, {2, 1}});
  MultiviewRegistrationParams params;
  params.min_overlap = 0.0;  // only the given pairs in the global step
  registration.setParams (params);
  const MultiviewRegistrationResult result = registration.compute (inputs);
  ASSERT_EQ (result.registeredCount (), 3u);
  EXPECT_EQ (result.views[2].reference, 0);
  EXPECT_EQ (result.views[1].reference, 2);
  EXPECT_EQ (result.views[1].references_tried, 1u);
  EXPECT_EQ (result.pairs, (ViewPairs{{0, 2}, {1, 2}}));
}

TEST (MultiviewTensorRegistration, UnusableViewIsReportedNotThrown)
{
  const auto& views = exampleRing ();
  pcl::PointCloud<pcl::PointXYZ>::Ptr empty (new pcl::PointCloud<pcl::PointXYZ>);
  const std::vector<MultiviewInput> inputs{inputOf (views[0], "v0"), {"empty", empty, pcl::ScanViewpoint::fromPositiveZ (), nullptr},
                                           inputOf (views[1], "v1")};
  MultiviewTensorRegistration registration;
  const MultiviewRegistrationResult result = registration.compute (inputs);
  EXPECT_FALSE (result.views[1].registered);
  EXPECT_FALSE (result.views[1].error.empty ());
  EXPECT_TRUE (result.views[2].registered);

  registration.setPairs ({{0, 3}});
  EXPECT_THROW (registration.compute (inputs), pcl::BadArgumentException);
}

TEST (MultiviewTensorRegistration, GlobalVerificationRefusalMovesOnToTheNextMatch)
{
  // The hook itself: TensorRegistration asks the acceptor about every locally verified hypothesis;
  // one that always refuses leaves the views unregistered after trying further matches.
  const auto& views = exampleRing ();
  TensorRegistrationParams params;
  params.scene_tensor_batches = 1;
  params.probe_rivals = false;  // the acceptor is asked about each probed rival that passes too
  const auto model = prepareTensorView (*views[0].view.cloud, views[0].view.viewpoint, params.preparation);
  const auto scene = prepareTensorView (*views[1].view.cloud, views[1].view.viewpoint, params.preparation);
  const auto dims = pcl::computeObjectDimensions<pcl::PointNormal> ({model->scan->fine.cloud.get (), scene->scan->fine.cloud.get ()});
  const auto register_with = [&] (const HypothesisAcceptor& accept) {
    TensorRegistration<pcl::PointXYZ> registration;
    registration.setParams (params);
    registration.setObjectDimensions (dims);
    registration.setInputTarget (views[0].view.cloud);
    registration.setInputSource (views[1].view.cloud);
    registration.setTargetView (withTensors (*model, dims, params));
    registration.setSourceView (withTensors (*scene, dims, params));
    registration.setHypothesisAcceptor (accept);
    pcl::PointCloud<pcl::PointXYZ> aligned;
    registration.align (aligned);
    return registration.getReport ();
  };

  std::size_t asked = 0;
  Eigen::Matrix4f seen = Eigen::Matrix4f::Zero ();
  const TensorRegistrationReport accepted = register_with ([&] (const TensorVerificationResult& r) {
    ++asked;
    seen = r.transform;
    return r.passed ();
  });
  ASSERT_TRUE (accepted.registered);
  EXPECT_EQ (asked, 1u);
  EXPECT_EQ (accepted.hypotheses_refused, 0u);
  // The acceptor judges the pose the registration reports: between the views' own frames, not
  // between the centred meshes the search works on (the meshes' origins are centimetres apart).
  ASSERT_GT ((model->origin - scene->origin).norm (), 10.0 * accepted.resolution);
  EXPECT_EQ (seen, accepted.transform);

  // Global verification with a D 10 d_res too small refuses the true pose and every repeat of it.
  pcl::ObjectDimensions small = dims;
  small.D.array () -= 10.0 * accepted.resolution;
  GlobalVerification global (small, accepted.resolution);
  global.addView (*model->scan->fine.cloud, Eigen::Affine3d (Eigen::Translation3d (model->origin)));
  const Eigen::Affine3d scene_mesh_to_view (Eigen::Translation3d (scene->origin));
  const TensorRegistrationReport refused = register_with ([&] (const TensorVerificationResult& r) {
    return global.accepts (*scene->scan->fine.cloud, Eigen::Affine3d (r.transform.cast<double> ()) * scene_mesh_to_view);
  });
  EXPECT_FALSE (refused.registered);
  EXPECT_GE (refused.hypotheses_refused, 1u);
  EXPECT_GT (refused.hypotheses_tried, accepted.hypotheses_tried) << "no further match was tried after the refusal";
  EXPECT_TRUE (refused.transform.isIdentity ());
}

TEST (MultiviewTensorRegistration, BadParametersAreRefusedBeforeAnyViewIsRead)
{
  // setParams checks every value: a bad global-step value no longer waits for the pairwise work.
  const auto refuses = [] (const std::function<void (MultiviewRegistrationParams&)>& spoil) {
    MultiviewRegistrationParams params;
    spoil (params);
    MultiviewTensorRegistration registration;
    EXPECT_THROW (registration.setParams (params), pcl::BadArgumentException);
    EXPECT_THROW (checkParams (params), pcl::BadArgumentException);
  };
  refuses ([] (auto& p) { p.global.max_distance = -1.0; });
  refuses ([] (auto& p) { p.global.sample_points = 0; });
  refuses ([] (auto& p) { p.global.max_normal_angle = 200.0; });
  refuses ([] (auto& p) { p.global.min_rotation = std::numeric_limits<double>::quiet_NaN (); });
  refuses ([] (auto& p) { p.global_verification.tolerance = -1.0; });
  refuses ([] (auto& p) { p.global_verification.checked_dimensions = 4; });
  refuses ([] (auto& p) { p.object_dimensions = Eigen::Vector3d (1.0, 0.0, 1.0); });
  refuses ([] (auto& p) { p.max_references = -2; });
  refuses ([] (auto& p) { p.min_overlap = 1.5; });
  refuses ([] (auto& p) { p.pairwise.grid_size = 0; });
  MultiviewTensorRegistration registration;
  EXPECT_NO_THROW (registration.setParams (MultiviewRegistrationParams ()));
}

TEST (MultiviewTensorRegistration, KnownDimensionsReplaceEq1)
{
  const auto& views = exampleRing ();
  const std::vector<MultiviewInput> inputs{inputOf (views[0], "v0"), inputOf (views[1], "v1")};
  MultiviewTensorRegistration registration;
  MultiviewRegistrationParams params;
  params.object_dimensions = Eigen::Vector3d (0.1, 0.3, 0.2);
  registration.setParams (params);
  const MultiviewRegistrationResult known = registration.compute (inputs);
  EXPECT_EQ (known.dimensions.D, Eigen::Vector3d (0.3, 0.2, 0.1));  // sorted, largest first, as Eq. 1 gives

  params.object_dimensions.setZero ();
  registration.setParams (params);
  const MultiviewRegistrationResult measured = registration.compute (inputs);
  const auto eq1 = pcl::computeObjectDimensions<pcl::PointNormal> (
      {measured.views[0].prepared->fine.cloud.get (), measured.views[1].prepared->fine.cloud.get ()});
  EXPECT_EQ (measured.dimensions.D, eq1.D);
}

namespace
{
  /** The example ring in a shuffled order (fixed seed): input k is ring view order[k]. */
  std::vector<int>
  shuffledOrder (std::size_t n, unsigned seed)
  {
    std::vector<int> order (n);
    std::iota (order.begin (), order.end (), 0);
    std::shuffle (order.begin (), order.end (), std::mt19937 (seed));
    return order;
  }
}

TEST (MultiviewTensorRegistration, ShuffledViewsAreRegisteredFromRankedPairs)
{
  const auto& views = exampleRing ();
  const std::vector<int> order = shuffledOrder (views.size (), 3);
  std::vector<MultiviewInput> inputs;
  for (const int i : order)
    inputs.push_back (inputOf (views[i], "view" + std::to_string (i)));
  const MultiviewRegistrationResult result = MultiviewTensorRegistration ().compute (inputs);

  ASSERT_EQ (result.registeredCount (), views.size ());
  EXPECT_EQ (result.components, 1);
  EXPECT_EQ (result.reference, 0) << "the lowest index keeps its frame";
  EXPECT_EQ (result.joins.size (), views.size () - 1) << "a spanning tree joins n views with n - 1 pairs";
  const std::size_t all_pairs = views.size () * (views.size () - 1) / 2;
  EXPECT_EQ (result.candidates.size (), all_pairs);
  EXPECT_LT (result.attempts.size (), all_pairs / 2) << "ranking should spare most full registrations";
  const auto& truth_of_reference = views[order[0]].view.pose;
  for (std::size_t k = 0; k < inputs.size (); ++k)
  {
    const auto& v = result.views[k];
    EXPECT_EQ (v.component, 0);
    EXPECT_EQ (v.reference < 0, static_cast<int> (k) == result.reference) << v.name << ": only the reference has no partner";
    const auto error = poseError (result, v.pose, truth_of_reference, views[order[k]].view.pose);
    EXPECT_LT (error.rotation_deg, 0.5) << v.name;
    EXPECT_LT (error.translation_resolutions, 2.0) << v.name;
  }
}

TEST (MultiviewTensorRegistration, TwoObjectsMakeTwoComponents)
{
  // Four neighbouring views of each of two different objects, interleaved: no pair across them
  // verifies, so each object's views form a model of their own, none is thrown away.
  pcl::ExampleObjectParams other_params;
  other_params.seed = 77;
  static const std::vector<pcl::SyntheticView> other = ringViews (pcl::makeExampleObject (other_params), 4);
  const auto& views = exampleRing ();
  std::vector<MultiviewInput> inputs;
  for (int i = 0; i < 4; ++i)
  {
    inputs.push_back (inputOf (views[i], "a" + std::to_string (i)));
    inputs.push_back (inputOf (other[i], "b" + std::to_string (i)));
  }
  const MultiviewRegistrationResult result = MultiviewTensorRegistration ().compute (inputs);

  ASSERT_EQ (result.components, 2);
  EXPECT_EQ (result.registeredCount (), inputs.size ());
  for (std::size_t k = 0; k < inputs.size (); ++k)
  {
    const auto& v = result.views[k];
    const bool first_object = k % 2 == 0;
    EXPECT_EQ (v.component, result.views[first_object ? 0 : 1].component) << v.name;
    const auto& ring = first_object ? views : other;
    const int reference = first_object ? 0 : 1;  // the lowest index of each component keeps its frame
    const auto error = poseError (result, v.pose, ring[0].view.pose, ring[k / 2].view.pose);
    EXPECT_LT (error.rotation_deg, 0.5) << v.name;
    EXPECT_LT (error.translation_resolutions, 2.0) << v.name;
    EXPECT_EQ (v.reference < 0, static_cast<int> (k) == reference) << v.name;
  }
  EXPECT_NE (result.views[0].component, result.views[1].component);
  for (const int c : {0, 1})
    EXPECT_EQ (registeredIntegrationViews (result, c).size (), 4u);
}

TEST (MultiviewTensorRegistration, RankedSearchGivesTheSameResultOnAnyNumberOfThreads)
{
  // Six neighbouring views of the ring, shuffled: enough for several batches of pairs.
  const auto& views = exampleRing ();
  const std::vector<int> order = shuffledOrder (6, 5);
  std::vector<MultiviewInput> inputs;
  for (const int i : order)
    inputs.push_back (inputOf (views[i], "view" + std::to_string (i)));
  std::vector<MultiviewRegistrationResult> results;
  for (const unsigned threads : {1u, 2u, 4u})
  {
    MultiviewTensorRegistration registration;
    registration.setNumberOfThreads (threads);
    results.push_back (registration.compute (inputs));
  }
  ASSERT_EQ (results[0].registeredCount (), inputs.size ());
  EXPECT_GE (results[0].attempts.size (), inputs.size () - 1);
  for (std::size_t r = 1; r < results.size (); ++r)
  {
    ASSERT_EQ (results[r].attempts.size (), results[0].attempts.size ());
    for (std::size_t a = 0; a < results[0].attempts.size (); ++a)
      EXPECT_TRUE (results[r].attempts[a].first == results[0].attempts[a].first &&
                   results[r].attempts[a].second == results[0].attempts[a].second);
    for (std::size_t k = 0; k < inputs.size (); ++k)
      EXPECT_TRUE (results[r].views[k].pose.matrix () == results[0].views[k].pose.matrix ()) << inputs[k].name;
  }
}

namespace
{
  /** The example ring with the true poses (relative to view 0) given for the views \a known marks. */
  std::vector<MultiviewInput>
  ringWithKnownPoses (const std::vector<bool>& known)
  {
    const auto& views = exampleRing ();
    std::vector<MultiviewInput> inputs;
    for (std::size_t i = 0; i < views.size (); ++i)
    {
      inputs.push_back (inputOf (views[i], "view" + std::to_string (i)));
      inputs.back ().pose_known = known[i];
      inputs.back ().known_pose = views[0].view.pose.inverse () * views[i].view.pose;
    }
    return inputs;
  }

  /** Views of kept poses keep them to the bit; the others are within 0.5 deg and 2 d_res of the truth. */
  void
  expectKeptAndRegistered (const MultiviewRegistrationResult& result, const std::vector<MultiviewInput>& inputs)
  {
    const auto& views = exampleRing ();
    ASSERT_EQ (result.registeredCount (), inputs.size ());
    EXPECT_EQ (result.components, 1);
    for (std::size_t i = 0; i < inputs.size (); ++i)
    {
      const auto& v = result.views[i];
      EXPECT_EQ (v.pose_kept, inputs[i].pose_known) << v.name;
      if (inputs[i].pose_known)
      {
        EXPECT_TRUE (v.pose.matrix () == inputs[i].known_pose.matrix ()) << v.name << ": a kept pose moved";
      }
      const auto error = poseError (result, v.pose, views[0].view.pose, views[i].view.pose);
      EXPECT_LT (error.rotation_deg, 0.5) << v.name;
      EXPECT_LT (error.translation_resolutions, 2.0) << v.name;
    }
  }
}

// A model extended with new views: the views of known poses are one group from the start, no pair
// among them is ranked or registered, and the new views are registered to them in their frame.
TEST (MultiviewTensorRegistration, KnownPosesAreKeptAndOnlyNewViewsRegistered)
{
  std::vector<bool> known (12, true);
  known[0] = known[7] = false;  // the lowest index is new: the frame is still the known views'
  const auto inputs = ringWithKnownPoses (known);
  const MultiviewRegistrationResult result = MultiviewTensorRegistration ().compute (inputs);
  expectKeptAndRegistered (result, inputs);
  EXPECT_EQ (result.candidates.size (), 2u * 10u + 1u) << "only pairs with a new view are ranked";
  for (const auto& a : result.attempts)
    EXPECT_TRUE (!known[a.first] || !known[a.second]) << a.first << "-" << a.second << " were both known";
  EXPECT_EQ (result.reference, 1) << "the lowest known view's frame";
  for (const auto& p : result.pairs)
    EXPECT_TRUE (!known[p.first] || !known[p.second]) << "the global step paired two fixed views";
  EXPECT_FALSE (result.pairs.empty ());
}

TEST (MultiviewTensorRegistration, KnownPosesAreKeptInOrderedSearch)
{
  std::vector<bool> known (12, false);
  for (int i = 0; i < 6; ++i)
    known[i] = true;
  const auto inputs = ringWithKnownPoses (known);
  MultiviewRegistrationParams params;
  params.search = ViewSearch::ORDERED;
  MultiviewTensorRegistration registration;
  registration.setParams (params);
  const MultiviewRegistrationResult result = registration.compute (inputs);
  expectKeptAndRegistered (result, inputs);
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ (result.views[i].references_tried, 0u) << "a known view was registered";
}

// Every pose known: nothing is ranked or registered, and nothing moves.
TEST (MultiviewTensorRegistration, EveryPoseKnownRegistersNothing)
{
  const auto inputs = ringWithKnownPoses (std::vector<bool> (12, true));
  const MultiviewRegistrationResult result = MultiviewTensorRegistration ().compute (inputs);
  expectKeptAndRegistered (result, inputs);
  EXPECT_TRUE (result.candidates.empty ());
  EXPECT_TRUE (result.attempts.empty ());
  EXPECT_TRUE (result.pairs.empty ());
}

TEST (MultiviewTensorRegistration, KnownPoseThatIsNotRigidIsRefused)
{
  auto inputs = ringWithKnownPoses (std::vector<bool> (12, false));
  inputs[3].pose_known = true;
  inputs[3].known_pose.linear () *= 2.0;
  EXPECT_THROW (MultiviewTensorRegistration ().compute (inputs), pcl::BadArgumentException);
}
