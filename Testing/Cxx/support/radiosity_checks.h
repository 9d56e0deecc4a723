#pragma once
// What the radiosity engine tests share: small scenes and walks over a solution.

#include "sky/cie_sky.h"
#include "base/angles.h"
#include "hierarchy/cluster.h"
#include "base/error.h"
#include "evaluation/point_form_factor.h"
#include "hierarchy/polygon_element.h"
#include "radiosity_scenes.h"
#include "sky/sky_hierarchy.h"
#include "emitters/sky_patch_element.h"
#include "solver/solver.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <functional>

namespace terralux_test
{

using namespace terralux;
using namespace terralux_test;

inline RadiosityOptions fine()
{
  RadiosityOptions options;
  options.errorTolerance = 1e-4;
  options.minimumElementArea = 1e-4;
  options.visibilitySamples = 4;
  return options;
}
} // namespace terralux_test
