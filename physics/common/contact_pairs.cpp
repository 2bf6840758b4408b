#include "physics/common/contact_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/mesh/hex8_shape.hpp"
#include "framework/mesh/partition.hpp"
#include "physics/materials/elastic_material.hpp"

namespace railfe {

namespace {

// Volume of global hex8 element \p element in the reference configuration.
double element_volume(const Mesh& mesh, GlobalIndex element) {
  const ElementBlock& block = mesh.blocks[mesh.block_of(element)];
  const GlobalIndex* nodes = block.element_nodes(element - block.first_element);
  double x[8][3], gradient[3][8];
  for (int a = 0; a < 8; ++a)
    for (int d = 0; d < 3; ++d)
      x[a][d] = mesh.coordinates[3 * nodes[a] + d];
  const Hex8GaussTable& table = hex8_gauss_table();
  double volume = 0;
  for (int q = 0; q < 8; ++q)
    volume += hex8_gradients(x, table.dN[q], gradient);
  return volume;
}

// K A^2 / V of a face of area \p area on hex8 \p element: the bulk-modulus penalty for f = 1.
double bulk_face_stiffness(const Mesh& mesh, const MaterialTable& materials, GlobalIndex element,
                           double area) {
  const ElasticMaterial& material = materials.of_block(mesh.block_of(element));
  const double bulk = material.young / (3 * (1 - 2 * material.poisson));
  return bulk * area * area / element_volume(mesh, element);
}

int surface_index(const std::vector<GlobalIndex>& surface, GlobalIndex node) {
  return static_cast<int>(std::lower_bound(surface.begin(), surface.end(), node) - surface.begin());
}

}  // namespace

ContactPairs::ContactPairs(const std::vector<ContactPairSpec>& specs,
                           const MeshPartition& partition, const MaterialTable& materials,
                           const std::string& deck, const std::string& path)
    : specs_(specs), partition_(partition), materials_(materials), deck_(deck), path_(path) {
  for (const ContactPairSpec& spec : specs_) {
    surfaces_.push_back(contact_surface_nodes(spec, partition.mesh(), deck, path));
    const ContactSurfaceNodes& surface = surfaces_.back();
    std::array<double, 2> elastic{};  // mean shear modulus and Poisson's ratio of its faces
    for (const GlobalIndex element : surface.master_elements) {
      const ElasticMaterial& material = materials.of_block(partition.mesh().block_of(element));
      elastic[0] += material.lame().mu / static_cast<double>(surface.master_elements.size());
      elastic[1] += material.poisson / static_cast<double>(surface.master_elements.size());
    }
    master_elastic_.push_back(elastic);
    surface_.insert(surface_.end(), surface.slave_nodes.begin(), surface.slave_nodes.end());
    for (const auto& face : surface.master_faces)
      surface_.insert(surface_.end(), face.begin(), face.end());
  }
  std::sort(surface_.begin(), surface_.end());
  surface_.erase(std::unique(surface_.begin(), surface_.end()), surface_.end());
  owned_.assign(surface_.size(), -1);
  for (std::size_t i = 0; i < surface_.size(); ++i) {
    const LocalIndex local = partition.local_node(surface_[i]);
    if (local >= 0 && local < partition.n_owned_nodes())
      owned_[i] = local;
  }
  const std::size_t n = surface_.size();
  positions_.assign(3 * n, 0.0);
  increments_.assign(3 * n, 0.0);
  forces_.assign(3 * n, 0.0);
  touched_.assign(specs_.size(), false);
}

ContactPairs::~ContactPairs() = default;

void ContactPairs::share(const double* x, const double* u, const double* du,
                         const std::vector<int>* subset) {
  const std::size_t n = subset != nullptr ? subset->size() : surface_.size();
  const auto surface_index = [&](std::size_t k) {
    return subset != nullptr ? static_cast<std::size_t>((*subset)[k]) : k;
  };
  exchange_.assign(6 * n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const LocalIndex node = owned_[surface_index(k)];
    if (node < 0)
      continue;
    for (int d = 0; d < 3; ++d) {
      exchange_[3 * k + d] = x[3 * node + d] + u[3 * node + d];
      if (du)
        exchange_[3 * (n + k) + d] = du[3 * node + d];
    }
  }
  partition_.comm().sum_in_place(exchange_);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = surface_index(k);
    for (int d = 0; d < 3; ++d) {
      positions_[3 * i + d] = exchange_[3 * k + d];
      increments_[3 * i + d] = exchange_[3 * (n + k) + d];
    }
  }
}

void ContactPairs::initialise(const std::vector<double>& owned_mass, double solid_step,
                              const double* x, const double* u) {
  if (specs_.empty())
    return;
  const Mesh& mesh = partition_.mesh();
  std::vector<double> mass(surface_.size(), 0.0);
  for (std::size_t i = 0; i < surface_.size(); ++i)
    if (owned_[i] >= 0)
      mass[i] = owned_mass[owned_[i]];
  partition_.comm().sum_in_place(mass);
  share(x, u, nullptr);

  pairs_.clear();
  for (std::size_t p = 0; p < specs_.size(); ++p) {
    const ContactPairSpec& spec = specs_[p];
    const ContactSurfaceNodes& surface = surfaces_[p];
    PenaltyPairGeometry geometry;
    geometry.n_surface_nodes = static_cast<int>(surface_.size());
    geometry.mass = mass;
    geometry.slave_area = surface.slave_area;
    double lightest = 1e300;
    for (GlobalIndex node : surface.slave_nodes) {
      geometry.slave_nodes.push_back(surface_index(surface_, node));
      lightest = std::min(lightest, mass[geometry.slave_nodes.back()]);
    }
    double size_sum = 0;
    for (std::size_t f = 0; f < surface.master_faces.size(); ++f) {
      std::array<int, 4> face;
      double face_mass = 0;
      for (int a = 0; a < 4; ++a) {
        face[a] = surface_index(surface_, surface.master_faces[f][a]);
        face_mass += 0.25 * mass[face[a]];
      }
      geometry.master_faces.push_back(face);
      const double area = face_area(mesh, surface.master_faces[f]);
      size_sum += std::sqrt(area);
      double stiffness;
      if (spec.mass_penalty) {
        // The reduced mass of the lightest slave node and the face: with it the contact's
        // critical step is 2 dt / sqrt(f), so f < 4 never limits the step.
        const double reduced = lightest * face_mass / (lightest + face_mass);
        stiffness = spec.penalty_factor * reduced / (solid_step * solid_step);
      } else {
        stiffness = spec.penalty_factor *
                    bulk_face_stiffness(mesh, materials_, surface.master_elements[f], area);
      }
      geometry.face_stiffness.push_back(stiffness);
    }
    if (spec.slave_cap) {
      // A quarter of each slave face's f K A^2 / V to each of its nodes: on matching cubes a
      // node gets what the face under it has, so only coarser master faces are capped.
      geometry.slave_stiffness.assign(surface.slave_nodes.size(), 0.0);
      for (std::size_t f = 0; f < surface.slave_faces.size(); ++f) {
        const auto& nodes = surface.slave_faces[f];
        const double quarter = 0.25 * spec.penalty_factor *
                               bulk_face_stiffness(mesh, materials_, surface.slave_elements[f],
                                                   face_area(mesh, nodes));
        for (GlobalIndex node : nodes)
          geometry.slave_stiffness[surface_index(surface.slave_nodes, node)] += quarter;
      }
      // A node of a node set on no face of the set has no stiffness of its own: no cap.
      for (double& k : geometry.slave_stiffness)
        if (!(k > 0))
          k = 1e300;
    }
    PenaltyPairSettings settings;
    settings.name = spec.name;
    settings.damping_fraction = spec.damping_fraction;
    settings.friction = spec.friction;
    settings.search_interval = spec.search_interval;
    const double mean_size = size_sum / static_cast<double>(surface.master_faces.size());
    settings.search_margin = spec.search_margin > 0 ? spec.search_margin : 0.5 * mean_size;
    settings.longitudinal = spec.longitudinal;
    pairs_.emplace_back(std::move(geometry), settings);
  }
  // Check time refused deep starts in the reference positions; a preload can still move the
  // bodies into each other.
  std::vector<double> global(3 * static_cast<std::size_t>(mesh.n_nodes()), 0.0);
  for (std::size_t i = 0; i < surface_.size(); ++i)
    std::copy_n(&positions_[3 * i], 3, &global[3 * surface_[i]]);
  for (std::size_t p = 0; p < specs_.size(); ++p) {
    const std::string problem = start_penetration_problem(specs_[p], surfaces_[p], mesh, global);
    if (!problem.empty())
      throw RunError(deck_ + ": " + path_ + "/Contact pairs/" + specs_[p].name + ": " + problem +
                     " after the preload of Start from; " + kPlacementAdvice);
  }
}

bool ContactPairs::scale_masses(std::vector<double>& owned_mass) {
  std::vector<ContactMassScaling>& result = mass_scaling_;
  result.assign(pairs_.size(), ContactMassScaling{});
  bool scaled = false;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    const double target = specs_[p].mass_scaling_step;
    const PenaltyContactPair& pair = pairs_[p];
    const PenaltyPairGeometry& geometry = pair.geometry();
    if (!(target > 0))
      continue;
    result[p].step_before = pair.stable_step();  // reported even where nothing is needed
    if (!(target > pair.stable_step()) || geometry.face_stiffness.empty())
      continue;
    scaled = true;
    const double half = 0.5 * target / damped_step_factor(specs_[p].damping_fraction);
    const double q = half * half;
    const double stiffest_face =
        *std::max_element(geometry.face_stiffness.begin(), geometry.face_stiffness.end());
    const double stiffest_slave =
        geometry.slave_stiffness.empty()
            ? 1e300
            : *std::max_element(geometry.slave_stiffness.begin(), geometry.slave_stiffness.end());
    // The mass each surface node needs, 0 where it is not in the pair.
    std::vector<double> needed(surface_.size(), 0.0);
    for (std::size_t s = 0; s < geometry.slave_nodes.size(); ++s) {
      const double k = geometry.slave_stiffness.empty()
                           ? stiffest_face
                           : std::min(geometry.slave_stiffness[s], stiffest_face);
      double& m = needed[geometry.slave_nodes[s]];
      m = std::max(m, 2 * q * k);
    }
    for (std::size_t f = 0; f < geometry.master_faces.size(); ++f) {
      const double k = std::min(geometry.face_stiffness[f], stiffest_slave);
      for (int node : geometry.master_faces[f])
        needed[node] = std::max(needed[node], 2 * q * k);
    }
    double added = 0;
    long long raised = 0;
    for (std::size_t i = 0; i < surface_.size(); ++i) {
      const LocalIndex node = owned_[i];
      if (node < 0 || !(owned_mass[node] < needed[i]))
        continue;
      added += needed[i] - owned_mass[node];
      owned_mass[node] = needed[i];
      ++raised;
    }
    result[p].added_mass = partition_.comm().sum(added);
    result[p].nodes = partition_.comm().sum(raised);
  }
  return scaled;
}

void ContactPairs::add_forces(const double* x, const double* u, const double* du, double dt,
                              double* residual) {
  if (pairs_.empty())
    return;
  const Stopwatch clock;
  // The largest surface speed, from the owners' increments: the pairs' searches need it before
  // the positions are shared, to know whether this step shares them all or only the windows.
  double fastest = 0;
  if (dt > 0) {
    double largest = 0;  // squared
    for (std::size_t i = 0; i < surface_.size(); ++i) {
      const LocalIndex node = owned_[i];
      if (node >= 0) {
        const double* increment = du + 3 * node;
        largest = std::max(largest, increment[0] * increment[0] + increment[1] * increment[1] +
                                        increment[2] * increment[2]);
      }
    }
    fastest = std::sqrt(partition_.comm().max(largest)) / dt;
  }
  bool all_nodes = false;
  for (const PenaltyContactPair& pair : pairs_)
    all_nodes = all_nodes || !pair.window_suffices(dt, fastest);
  // Between searches every pair reads only its window (the surface nodes that can meet before
  // the next search), a small part of the surfaces.
  if (all_nodes) {
    share(x, u, du);
    std::fill(forces_.begin(), forces_.end(), 0.0);
  } else {
    share(x, u, du, &window_);
    for (int i : window_)
      std::fill_n(&forces_[3 * static_cast<std::size_t>(i)], 3, 0.0);
  }
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    pairs_[p].evaluate(positions_.data(), increments_.data(), dt, fastest, forces_.data());
    if (pairs_[p].totals().active > 0)
      touched_[p] = true;
  }
  const auto add = [&](std::size_t i) {
    const LocalIndex node = owned_[i];
    if (node >= 0)
      for (int d = 0; d < 3; ++d)
        residual[3 * node + d] += forces_[3 * i + d];
  };
  if (all_nodes) {
    for (std::size_t i = 0; i < surface_.size(); ++i)
      add(i);
    window_.clear();
    for (const PenaltyContactPair& pair : pairs_)
      window_.insert(window_.end(), pair.window_nodes().begin(), pair.window_nodes().end());
    std::sort(window_.begin(), window_.end());
    window_.erase(std::unique(window_.begin(), window_.end()), window_.end());
  } else {
    for (int i : window_)
      add(static_cast<std::size_t>(i));
  }
  seconds_ += clock.seconds();
}

double ContactPairs::stable_step() const {
  double step = 1e300;
  for (const PenaltyContactPair& pair : pairs_)
    step = std::min(step, pair.stable_step());
  return step;
}

std::string ContactPairs::critical_pair() const {
  std::string name;
  double step = 1e300;
  for (const PenaltyContactPair& pair : pairs_) {
    if (pair.stable_step() < step) {
      step = pair.stable_step();
      name = pair.settings().name;
    }
  }
  return name;
}

double ContactPairs::stored_energy() const {
  double energy = 0;
  for (const PenaltyContactPair& pair : pairs_)
    energy += pair.totals().stored_energy;
  return energy;
}

double ContactPairs::dissipated() const {
  double energy = 0;
  for (const PenaltyContactPair& pair : pairs_)
    energy += pair.totals().dissipated;
  return energy;
}

std::vector<double> ContactPairs::state() const {
  std::vector<double> values;
  for (const PenaltyContactPair& pair : pairs_) {
    const std::vector<double> pair_state = pair.state();
    values.push_back(static_cast<double>(pair_state.size()));
    values.insert(values.end(), pair_state.begin(), pair_state.end());
  }
  return values;
}

bool ContactPairs::restore(const std::vector<double>& values) {
  std::size_t at = 0;
  for (PenaltyContactPair& pair : pairs_) {
    if (at >= values.size())
      return false;
    const auto size = static_cast<std::size_t>(values[at]);
    if (at + 1 + size > values.size())
      return false;
    if (!pair.restore(
            std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(at + 1),
                                values.begin() + static_cast<std::ptrdiff_t>(at + 1 + size))))
      return false;
    at += 1 + size;
  }
  return at == values.size();
}

}  // namespace railfe
