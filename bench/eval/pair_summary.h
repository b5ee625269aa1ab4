/*
 * pcl_tensor evaluation: CSV rows and the summary of a set of scored pairs.
 */
#pragma once

#include "pair_evaluation.h"

#include <string>
#include <vector>

namespace pcl_tensor_eval
{
  /** \brief Write one CSV row per pair (with a header) to \a path.
    * \throw std::runtime_error when the file cannot be written
    */
  void
  writePairCsv (const std::string& path, const std::vector<PairResult>& results);

  /** \brief Median of \a values (NaN skipped; NaN when none is left). */
  double
  median (std::vector<double> values);

  /** \brief Print the summary of issue 5: correct/total per overlap band, registrations reported on
    * pairs with overlap < 0.1, wrong registrations, median errors of the correct ones and median time.
    */
  void
  printPairSummary (const std::string& title, const std::vector<PairResult>& results);
}
