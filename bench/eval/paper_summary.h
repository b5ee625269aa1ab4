/*
 * pcl_tensor evaluation: the rows of doc/results.md, the paper's figure beside ours, as CSV.
 */
#pragma once

#include "pair_evaluation.h"

#include <functional>
#include <string>
#include <vector>

namespace pcl_tensor_eval
{
  /** \brief One quantity of one experiment: the paper's value, ours, and the PCL baselines' where measured.
    * Empty cells mean "not measured"; no cell may hold a comma.
    */
  struct SummaryRow
  {
    std::string figure;    ///< the paper's figure or section
    std::string quantity;  ///< what is measured, and on which data
    std::string paper;     ///< the paper's value (or "-" where the paper gives none)
    std::string tensor;    ///< ours
    std::string fpfh;      ///< PCL FPFH + SampleConsensusPrerejective + ICP
    std::string spin;      ///< PCL spin images
  };

  /** \brief Write \a rows with a header. \throw std::runtime_error when the file cannot be written or a cell holds a comma */
  void
  writeSummaryCsv (const std::string& path, const std::vector<SummaryRow>& rows);

  /** \brief "k/n (p%)", or "0/0" when n is 0. */
  std::string
  fractionText (std::size_t k, std::size_t n);

  /** \brief \a value with \a decimals decimals, "-" when NaN. */
  std::string
  numberText (double value, int decimals);

  /** \brief Count the results that satisfy \a pred. */
  std::size_t
  countIf (const std::vector<PairResult>& results, const std::function<bool (const PairResult&)>& pred);

  /** \brief The results whose overlap lies in [lo, hi). */
  std::vector<PairResult>
  inOverlap (const std::vector<PairResult>& results, double lo, double hi);

  /** \brief Per overlap bin of \a width: pairs, correct and wrong registrations (Fig. 18's data).
    * Columns: label,overlap_lo,overlap_hi,pairs,correct,wrong,correct_pct.
    * \throw std::runtime_error when the file cannot be written */
  void
  appendOverlapBins (const std::string& path, const std::string& label, const std::vector<PairResult>& results, double width,
                     bool header);
}
