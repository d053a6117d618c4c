#pragma once
// ImGui's sliders, drags and colour pickers edit floats; the graph keeps doubles and saves
// the shortest decimal that reads back to the same double. A float widened as it is
// (3.753f is 3.753000020980835) would be saved with all of its binary tail, and a vec3
// whose one component was dragged would have the other two rewritten the same way.
#include <vector>

namespace wg::editor {

// The shortest decimal that reads back to the same float, as a double: 3.753f -> 3.753.
double decimalOfFloat(float shown);

// The value after a widget edited `shown` (the floats it was given, from `before`): a
// component the widget left as it was keeps its exact double; an edited one is
// decimalOfFloat of the float. Sizes differ: `shown` converted as edited.
std::vector<double> valuesFromWidget(const std::vector<double>& before, const std::vector<float>& shown);

}  // namespace wg::editor
