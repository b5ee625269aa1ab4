/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/io/registration_report_json.h>
#include <pcl/registration/tensor_registration_report.h>

#include <string>
#include <vector>

namespace pcl
{
  namespace io
  {
    /** \brief One pair registration made elsewhere (pcl_tensor_pairs --pairs), for the graph and
      * the global step of another process (pcl_tensor_model --pairs-results).
      * \ingroup io
      */
    struct ViewPairResult
    {
      /** The views' ids (viewIdOf()): the keys, which tell views apart whatever path named them. */
      std::string model, scene;
      /** The views' file names as the registering tool was given them: for people, not for lookup. */
      std::string model_file, scene_file;
      /** registerTensorViews() of scene into model's frame. Read back: every field toJson() writes;
        * verification holds transform, icp_fitness, fine_correspondences and stage PASSED when
        * registered, and the first rival pose when ambiguous. */
      pcl::registration::TensorRegistrationReport report;
    };

    /** \brief A result for the views in files \a model_file and \a scene_file, their ids by viewIdOf(). */
    ViewPairResult
    makeViewPairResult (const std::string& model_file, const std::string& scene_file,
                        const pcl::registration::TensorRegistrationReport& report);

    /** \brief One result as one JSON object: "model_file", "model_id", "scene_file", "scene_id" and
      * "report" (toJson(const TensorRegistrationReport&)). Each float of the transforms is written
      * as its double, in the shortest digits that read back to it: the poses survive bit for bit. */
    JsonReport
    toJson (const ViewPairResult& result);

    /** \brief The report toJson(const TensorRegistrationReport&) wrote, restored (what it does not
      * write keeps its default).
      * \throw pcl::IOException naming the first field missing or of the wrong type */
    pcl::registration::TensorRegistrationReport
    registrationReportFromJson (const JsonReport& json);

    /** \brief \a results as a results file: JSON lines, one result per line, in order. */
    std::string
    formatViewPairResults (const std::vector<ViewPairResult>& results);

    /** \brief Write \a results to \a path (formatViewPairResults()) atomically (AtomicFileWriter):
      * a reader sees all of them or the file as it was.
      * \throw pcl::IOException when the file cannot be written */
    void
    saveViewPairResults (const std::string& path, const std::vector<ViewPairResult>& results);

    /** \brief Read a results file (saveViewPairResults()); blank lines are skipped, an empty file gives
      * no result.
      * \throw pcl::IOException when the file cannot be read, or a line is not a result (the message
      *        gives the file and line number) */
    std::vector<ViewPairResult>
    loadViewPairResults (const std::string& path);

    /** \brief What a search capped at \a max_hypotheses (0: no cap) would have reported, from the
      * report of a search with a larger cap (pcl_tensor_pairs searches fully): the same when it tried
      * no more than \a max_hypotheses, since hypotheses are tried in one order whatever the cap;
      * otherwise not registered after \a max_hypotheses. A ViewPairRegistration callback answering
      * from results calls it, so that MultiviewTensorRegistration's first pass (first_pass_hypotheses)
      * refuses, and its full pass retries, the same pairs as when it registers them itself. */
    pcl::registration::TensorRegistrationReport
    reportWithinHypotheses (const pcl::registration::TensorRegistrationReport& report, int max_hypotheses);
  }
}
