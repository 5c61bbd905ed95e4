// What a case file says for EN 13201 road lighting (docs/road.md): the roads whose field of
// calculation is checked against their lighting class. Read by study/compliance/en13201_case.cpp;
// the study is study/compliance/en13201.h.
#pragma once

#include "base/error.h"
#include "base/math.h"
#include "metrics/en13201.h"

#include <string>
#include <vector>

namespace candela {

// A [[road]]: a straight carriageway on the plane z = 0. Its field of calculation starts at
// `start` (a plan point on the road's near edge) and runs `lengthM` (the spacing between two
// luminaires of a row) along `direction`; the road spans `widthM` to the left of `direction`, in
// `lanes` lanes of equal width.
struct RoadSpec {
  std::string name;
  Vec2 start{0.0};
  Vec2 direction{1.0, 0.0};  // unit
  double lengthM = 0.0, widthM = 0.0;
  int lanes = 1;
  RoadClass roadClass;
  std::vector<AdditionalRoadClass> additional;  // `additional_classes`: at most one SC and one EV
  std::string surface = "R3";  // an r-table metrics/en13201.h has
  double q0 = 0.0;             // sr⁻¹; the table's own when not given
  FileLoc loc;
};

// Everything of a case that only EN 13201 reads.
struct RoadLightingSpec {
  std::vector<RoadSpec> roads;
};

}  // namespace candela
