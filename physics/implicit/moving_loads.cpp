#include "physics/implicit/moving_loads.hpp"

#include "framework/base/error.hpp"
#include "physics/elements/beam_interpolation.hpp"
#include "physics/implicit/beam_paths.hpp"

namespace railfe {

void add_moving_load_parameters(ParameterSpec& spec) {
  ParameterSpec load(
      "A force of fixed direction travelling along beams at constant speed (Frýba's moving "
      "force): the work-consistent nodal load of the element beneath it; zero off the path.");
  load.required_text_array(
      "Path",
      "Beam2 blocks whose elements form one chain, travelled from its end with the "
      "smallest (x, y, z).");
  load.real("Start", 0.0, "Arc length along the path at t = 0 (negative: not yet on it).", "m");
  load.required_real("Speed", "Speed along the path.", "m/s");
  load.required_real_array("Force", "The force P.", "N", 3);
  load.text("Function", "1", "Scale of P as a function of time t (s).");
  spec.named_sublists("Moving loads", load, "Forces travelling along beams (models with beams).");
}

std::vector<MovingLoadSpec> read_moving_loads(const Teuchos::ParameterList& step,
                                              const std::string& deck, const std::string& path) {
  std::vector<MovingLoadSpec> specs;
  const auto& list = step.sublist("Moving loads");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const auto& entry = list.sublist(list.name(it));
    MovingLoadSpec spec;
    spec.name = list.name(it);
    for (const auto& block : entry.get<Teuchos::Array<std::string>>("Path"))
      spec.blocks.push_back(block);
    spec.start = entry.get<double>("Start");
    spec.speed = entry.get<double>("Speed");
    const auto force = entry.get<Teuchos::Array<double>>("Force");
    for (int d = 0; d < 3; ++d)
      spec.force[d] = force[d];
    spec.function = entry.get<std::string>("Function");
    Expression(spec.function, deck, path + "/Moving loads/" + spec.name + "/Function");
    specs.push_back(spec);
  }
  return specs;
}

MovingLoads::MovingLoads(const std::vector<MovingLoadSpec>& specs, const Mesh& mesh,
                         const SectionTable& sections,
                         const std::function<long(GlobalIndex, int)>& unknown,
                         const std::string& deck, const std::string& path) {
  for (const MovingLoadSpec& spec : specs) {
    const std::string where = path + "/Moving loads/" + spec.name;
    const auto chain = chain_of_blocks(mesh, spec.blocks, deck, where + "/Path");
    loads_.push_back({make_beam_path(mesh, sections, chain, unknown), spec.start, spec.speed,
                      Eigen::Vector3d(spec.force[0], spec.force[1], spec.force[2]),
                      Expression(spec.function, deck, where + "/Function")});
  }
}

void MovingLoads::add(double time, double* force) const {
  for (const Load& load : loads_) {
    std::size_t index = 0;
    double xi = 0;
    if (!load.path.locate(load.start + load.speed * time, index, xi))
      continue;
    const PathElement& element = load.path.element(index);
    const Eigen::Matrix<double, 12, 1> nodal =
        beam_translation_interpolation(element.beam, xi).transpose() *
        (load.scale(0, 0, 0, time) * load.force);
    for (int k = 0; k < 12; ++k)
      if (element.unknowns[k] >= 0)
        force[element.unknowns[k]] += nodal[k];
  }
}

}  // namespace railfe
