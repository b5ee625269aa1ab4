/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#pragma once

#include <pcl/exceptions.h>

#include <sstream>
#include <string>

namespace pcl
{
  /** \brief Thrown when a range scan or mesh cannot be used: empty, all NaN, fewer than three points,
    * degenerate (collinear) geometry, or a mesh without faces.
    *
    * File problems are reported with pcl::IOException and out-of-range parameters with
    * pcl::BadArgumentException, so that callers can tell bad data from bad files and bad settings.
    * \ingroup common
    */
  class InvalidScanException : public PCLException
  {
    public:
      explicit InvalidScanException (const std::string& error_description,
                                     const char* file_name = nullptr,
                                     const char* function_name = nullptr,
                                     unsigned line_number = 0)
        : PCLException (error_description, file_name, function_name, line_number)
      {}
  };

  /** \brief Thrown when a computation would need more memory than its configured limit (e.g. a voxel
    * grid too fine for the object); nothing large has been allocated when it is thrown.
    * \ingroup common
    */
  class MemoryLimitException : public PCLException
  {
    public:
      explicit MemoryLimitException (const std::string& error_description,
                                     const char* file_name = nullptr,
                                     const char* function_name = nullptr,
                                     unsigned line_number = 0)
        : PCLException (error_description, file_name, function_name, line_number)
      {}
  };

  /** \brief The description of an exception without the ": " that pcl::PCLException puts before it
    * when no file name is given; for one-line messages in the apps.
    */
  inline std::string
  errorDescription (const std::exception& e)
  {
    std::string message = e.what ();
    return message.rfind (": ", 0) == 0 ? message.substr (2) : message;
  }
}

/** \brief Throw \a ExceptionName with a streamed message, recording where it was thrown. */
#define PCL_TENSOR_THROW(ExceptionName, message)                                   \
  do {                                                                             \
    std::ostringstream pcl_tensor_throw_s_;                                        \
    pcl_tensor_throw_s_ << message;                                                \
    throw ExceptionName (pcl_tensor_throw_s_.str ());                              \
  } while (false)
