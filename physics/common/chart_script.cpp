#include "physics/common/chart_script.hpp"

#include <cstdlib>
#include <fstream>

#include "framework/app/module.hpp"

namespace railfe {

void draw_chart(StepContext& context, const std::string& section, const std::string& script,
                const std::vector<std::string>& arguments) {
  if (!context.model.comm().is_root())
    return;
  const std::string python =
      std::ifstream("/usr/bin/python3").good() ? "/usr/bin/python3" : "python3";
  std::string command = python + " '" RAILFE_SOURCE_DIR "/regression/charts/" + script + "'";
  for (const auto& argument : arguments)
    command += " '" + argument + "'";
  if (std::system((command + " > /dev/null 2>&1").c_str()) != 0)
    context.summary.add(section, "warning",
                        "the chart was not drawn (needs python3 with matplotlib): " + command);
}

}  // namespace railfe
