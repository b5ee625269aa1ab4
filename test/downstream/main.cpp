#include <pcl/common/object_dimensions.h>
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
  return d[0] > 0.0 ? 0 : 1;
}
