#include <pcl/common/object_dimensions.h>
#include <pcl/io/registration_report_json.h>
#include <pcl/simulation/example_object.h>

#include <iostream>

int
main ()
{
  pcl::ExampleObjectParams params;
  params.subdivisions = 2;
  const pcl::ScanMesh object = pcl::makeExampleObject (params);
  const Eigen::Vector3d d = pcl::principalExtents (*object.cloud);
  std::cout << "example object extents " << d.transpose () << std::endl;
  // pcl_tensor::io: the report writer of the apps.
  const std::string report = pcl::io::dumpJson (pcl::io::toJson (pcl::registration::TensorRegistrationReport{}));
  std::cout << "empty report " << report << std::endl;
  return d[0] > 0.0 && report.find ("\"not_registered\"") != std::string::npos ? 0 : 1;
}
