/*
 * pcl_tensor: a progress bar per stage for the command-line tools, shown only on a terminal.
 */
#pragma once

#include <cstdio>
#include <string>

#include <unistd.h>

namespace pcl_tensor_tools
{
  /** One line on stderr per stage, redrawn in place: "pairwise      [#######.......]  7/15".
    * Silent when stderr is not a terminal, so logs and pipes get no control characters. */
  class ProgressBar
  {
    public:
      explicit ProgressBar (bool enabled = isatty (fileno (stderr)) != 0) : enabled_ (enabled) {}

      ~ProgressBar () { finish (); }

      /** \brief \a done of \a total steps of \a stage are finished; a new stage ends the previous line. */
      void
      update (const std::string& stage, std::size_t done, std::size_t total)
      {
        if (!enabled_)
          return;
        if (stage != stage_)
          finish ();
        stage_ = stage;
        const std::size_t width = 30;
        const std::size_t filled = total > 0 ? (done >= total ? width : width * done / total) : width;
        std::fprintf (stderr, "\r%-12s [%s%s] %zu/%zu", stage.c_str (), std::string (filled, '#').c_str (),
                      std::string (width - filled, '.').c_str (), done, total);
        std::fflush (stderr);
      }

      /** \brief End the current stage's line. */
      void
      finish ()
      {
        if (enabled_ && !stage_.empty ())
          std::fputc ('\n', stderr);
        stage_.clear ();
      }

    private:
      bool enabled_;
      std::string stage_;
  };
}
