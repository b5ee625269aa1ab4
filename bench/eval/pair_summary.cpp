/*
 * pcl_tensor evaluation: CSV rows and the summary of a set of scored pairs.
 */
#include "pair_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <stdexcept>

namespace pcl_tensor_eval
{
  void
  writePairCsv (const std::string& path, const std::vector<PairResult>& results)
  {
    std::ofstream out (path);
    if (!out)
      throw std::runtime_error ("cannot write " + path);
    out << "model,scene,overlap,resolution,registered,correct,wrong,rotation_error_deg,translation_error_res,"
           "centroid_error_res,correct_at_centroid,hypotheses,matches,fail_coarse_dimensions,fail_coarse_overlap,fail_fine_overlap,fail_fine_dimensions,fail_free_space,time_ms\n";
    out << std::setprecision (6);
    for (const PairResult& r : results)
    {
      out << r.model << ',' << r.scene << ',' << r.overlap << ',' << r.resolution << ',' << r.registered << ','
          << r.correct << ',' << r.wrong () << ',';
      // Empty cells, not "nan", when no transform was reported: spreadsheets read them as missing.
      if (r.registered)
        out << r.rotation_error_deg << ',' << r.translation_error_res << ',' << r.centroid_error_res << ',';
      else
        out << ",,,";
      out << r.correct_at_centroid << ',';
      out << r.hypotheses << ',' << r.matches;
      for (std::size_t k = 1; k < r.failures.size (); ++k)
        out << ',' << r.failures[k];
      out << ',' << r.time_ms << '\n';
    }
  }

  double
  median (std::vector<double> values)
  {
    values.erase (std::remove_if (values.begin (), values.end (), [] (double v) { return std::isnan (v); }), values.end ());
    if (values.empty ())
      return std::nan ("");
    std::sort (values.begin (), values.end ());
    const std::size_t n = values.size ();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  }

  namespace
  {
    void
    printBand (const std::vector<PairResult>& results, const char* label, double lo, double hi)
    {
      int total = 0, correct = 0, registered = 0, wrong = 0;
      for (const PairResult& r : results)
        if (r.overlap >= lo && r.overlap < hi)
        {
          ++total;
          correct += r.correct;
          registered += r.registered;
          wrong += r.wrong ();
        }
      std::printf ("  overlap %-10s %3d pairs: correct %3d (%5.1f%%)  registered %3d  wrong %d\n", label, total, correct,
                   total ? 100.0 * correct / total : 0.0, registered, wrong);
    }

    double
    medianOf (const std::vector<PairResult>& results, const std::function<double (const PairResult&)>& f)
    {
      std::vector<double> v;
      for (const PairResult& r : results)
        v.push_back (f (r));
      return median (v);
    }
  }

  void
  printPairSummary (const std::string& title, const std::vector<PairResult>& results)
  {
    if (results.empty ())
    {
      std::printf ("\n== %s: no pairs\n", title.c_str ());
      return;
    }
    int correct = 0, wrong = 0, correct_at_centroid = 0;
    for (const PairResult& r : results)
    {
      correct += r.correct;
      wrong += r.wrong ();
      correct_at_centroid += r.correct_at_centroid;
    }
    const double nan = std::nan ("");
    std::printf ("\n== %s: %zu pairs, correct %d (%.1f%%), WRONG registrations reported: %d\n", title.c_str (),
                 results.size (), correct, 100.0 * correct / results.size (), wrong);
    printBand (results, ">= 0.5", 0.5, 2.0);
    printBand (results, "0.3-0.5", 0.3, 0.5);
    printBand (results, "0.1-0.3", 0.1, 0.3);
    printBand (results, "< 0.1", -1.0, 0.1);
    std::printf ("  median over correct pairs: rotation error %.4f deg, translation error %.4f d_res (at the centroid %.4f d_res)\n",
                 medianOf (results, [&] (const PairResult& r) { return r.correct ? r.rotation_error_deg : nan; }),
                 medianOf (results, [&] (const PairResult& r) { return r.correct ? r.translation_error_res : nan; }),
                 medianOf (results, [&] (const PairResult& r) { return r.correct ? r.centroid_error_res : nan; }));
    std::printf ("  correct with the translation error taken at the scene's centroid: %d\n", correct_at_centroid);
    std::printf ("  median time per pair %.1f ms (max %.1f ms)\n", medianOf (results, [] (const PairResult& r) { return r.time_ms; }),
                 std::max_element (results.begin (), results.end (), [] (const PairResult& a, const PairResult& b) {
                   return a.time_ms < b.time_ms; })->time_ms);
  }
}
