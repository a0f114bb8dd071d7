// The built-in method families, one file each (internal to the registry, registry.cpp): each
// returns its methods' descriptors in the order the reports list them.
#pragma once

#include <vector>

#include "lexel/spatial/methods/method.h"

namespace lexel::spatial {

std::vector<MethodDescriptor> OptimizerMethods();    // optimizer_methods.cpp
std::vector<MethodDescriptor> BaselineMethods();     // baseline_methods.cpp
std::vector<MethodDescriptor> WarpedMethods();       // warped_methods.cpp
std::vector<MethodDescriptor> PartitionedMethods();  // partitioned_methods.cpp
std::vector<MethodDescriptor> TrapezoidMethods();    // trapezoid_methods.cpp
std::vector<MethodDescriptor> VirtualMethods();      // virtual_methods.cpp
std::vector<MethodDescriptor> BoundMethods();        // bound_methods.cpp

}  // namespace lexel::spatial
