/*
 * pcl_tensor evaluation: the rows of doc/results.md, the paper's figure beside ours, as CSV.
 */
#include "paper_summary.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace pcl_tensor_eval
{
  void
  writeSummaryCsv (const std::string& path, const std::vector<SummaryRow>& rows)
  {
    std::ofstream out (path);
    if (!out)
      throw std::runtime_error ("cannot write " + path);
    out << "figure,quantity,paper,tensor,fpfh,spin\n";
    for (const SummaryRow& r : rows)
    {
      for (const std::string* cell : {&r.figure, &r.quantity, &r.paper, &r.tensor, &r.fpfh, &r.spin})
        if (cell->find (',') != std::string::npos)
          throw std::runtime_error ("summary cell with a comma: " + *cell);
      out << r.figure << ',' << r.quantity << ',' << r.paper << ',' << r.tensor << ',' << r.fpfh << ',' << r.spin << '\n';
    }
  }

  std::string
  fractionText (std::size_t k, std::size_t n)
  {
    char text[64];
    if (n == 0)
      std::snprintf (text, sizeof text, "0/0");
    else
      std::snprintf (text, sizeof text, "%zu/%zu (%.0f%%)", k, n, 100.0 * static_cast<double> (k) / static_cast<double> (n));
    return text;
  }

  std::string
  numberText (double value, int decimals)
  {
    if (std::isnan (value))
      return "-";
    char text[64];
    std::snprintf (text, sizeof text, "%.*f", decimals, value);
    return text;
  }

  std::size_t
  countIf (const std::vector<PairResult>& results, const std::function<bool (const PairResult&)>& pred)
  {
    std::size_t n = 0;
    for (const PairResult& r : results)
      n += pred (r) ? 1 : 0;
    return n;
  }

  std::vector<PairResult>
  inOverlap (const std::vector<PairResult>& results, double lo, double hi)
  {
    std::vector<PairResult> selected;
    for (const PairResult& r : results)
      if (r.overlap >= lo && r.overlap < hi)
        selected.push_back (r);
    return selected;
  }

  void
  appendOverlapBins (const std::string& path, const std::string& label, const std::vector<PairResult>& results, double width,
                     bool header)
  {
    std::ofstream out (path, header ? std::ios::trunc : std::ios::app);
    if (!out)
      throw std::runtime_error ("cannot write " + path);
    if (header)
      out << "label,overlap_lo,overlap_hi,pairs,correct,wrong,correct_pct\n";
    const int bins = static_cast<int> (std::lround (1.0 / width));
    for (int b = 0; b < bins; ++b)
    {
      const double lo = b * width, hi = b + 1 == bins ? 1.01 : (b + 1) * width;
      const auto in = inOverlap (results, lo, hi);
      const std::size_t correct = countIf (in, [] (const PairResult& r) { return r.correct; });
      const std::size_t wrong = countIf (in, [] (const PairResult& r) { return r.wrong (); });
      out << label << ',' << lo << ',' << std::min (hi, 1.0) << ',' << in.size () << ',' << correct << ',' << wrong << ','
          << (in.empty () ? std::nan ("") : 100.0 * static_cast<double> (correct) / static_cast<double> (in.size ())) << '\n';
    }
  }
}
