#include "physics/explicit/solid_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include <Eigen/Dense>

#include "framework/mesh/hex8_shape.hpp"
#include "framework/mesh/hex8_topology.hpp"
#include "framework/mesh/partition.hpp"
#include "physics/common/solid_assembly.hpp"
#include "physics/elements/hex8.hpp"
#include "physics/elements/hex8_one_point.hpp"
#include "physics/explicit/solid_element_forces.hpp"
#include "physics/materials/elastic_material.hpp"

namespace railfe {

namespace {

// ω² of the hourglass stiffness on lumped masses m: C λ_max(Γ), Γ_αβ = Σ_a γ_αa γ_βa / m_a.
double hourglass_frequency_squared(const double gamma[32], const double masses[8],
                                   double hourglass_stiffness) {
  Eigen::Matrix4d gram = Eigen::Matrix4d::Zero();
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q)
      for (int a = 0; a < 8; ++a)
        gram(p, q) += gamma[p * 8 + a] * gamma[q * 8 + a] / masses[a];
  return hourglass_stiffness *
         Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(gram, Eigen::EigenvaluesOnly)
             .eigenvalues()
             .maxCoeff();
}

// Local elements of every hex8 block, ordered by their lowest local node so that neighbouring
// elements touch neighbouring memory.
std::vector<std::pair<const LocalBlock*, LocalIndex>> ordered_elements(
    const MeshPartition& partition, std::vector<LocalIndex>& partition_index,
    std::vector<GlobalIndex>& global_element) {
  std::vector<std::pair<const LocalBlock*, LocalIndex>> elements;
  std::vector<LocalIndex> key;
  const auto& blocks = partition.blocks();
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const LocalBlock& block = blocks[b];
    if (partition.mesh().blocks[block.block].type != ElementType::hex8)
      continue;
    for (LocalIndex e = 0; e < block.n_elements(); ++e) {
      elements.emplace_back(&block, e);
      partition_index.push_back(partition.first_local_element(b) + e);
      global_element.push_back(partition.mesh().blocks[block.block].first_element +
                               block.elements[e]);
      const LocalIndex* nodes = &block.connectivity[block.offsets[e]];
      key.push_back(*std::min_element(nodes, nodes + 8));
    }
  }
  std::vector<std::size_t> order(elements.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  std::vector<std::pair<const LocalBlock*, LocalIndex>> sorted;
  std::vector<LocalIndex> sorted_index;
  std::vector<GlobalIndex> sorted_global;
  for (std::size_t i : order) {
    sorted.push_back(elements[i]);
    sorted_index.push_back(partition_index[i]);
    sorted_global.push_back(global_element[i]);
  }
  partition_index = sorted_index;
  global_element = sorted_global;
  return sorted;
}

}  // namespace

SolidElements build_solid_elements(const MeshPartition& partition, const MaterialTable& materials,
                                   const SolidKernelSettings& settings) {
  SolidElements elements;
  const auto order = ordered_elements(partition, elements.partition_index, elements.global_element);
  const LocalIndex n = static_cast<LocalIndex>(order.size());
  const int n_points = settings.full_integration ? 8 : 1;
  elements.n_elements = n;
  elements.n_nodes = partition.n_local_nodes();
  elements.n_points = n_points;
  elements.nodes.resize(8 * static_cast<std::size_t>(n));
  elements.gradients.resize(24 * static_cast<std::size_t>(n) * n_points);
  if (n_points > 1)
    elements.weights.resize(static_cast<std::size_t>(n) * n_points);
  for (auto* field :
       {&elements.volume, &elements.lambda, &elements.mu, &elements.density, &elements.wave_speed,
        &elements.hourglass_scale, &elements.stable_step, &elements.length})
    field->resize(n);
  if (!settings.full_integration)
    elements.hourglass_projection.resize(12 * static_cast<std::size_t>(n));

  const Hex8GaussTable& table = hex8_gauss_table();
  for (LocalIndex e = 0; e < n; ++e) {
    const LocalBlock& block = *order[e].first;
    const LocalIndex local = order[e].second;
    std::copy_n(&block.connectivity[block.offsets[local]], 8, &elements.nodes[8 * e]);
    double x[8][3];
    element_coordinates(partition, block, local, x);
    const ElasticMaterial& material = materials.of_block(block.block);
    const LameConstants lame = material.lame();
    elements.lambda[e] = lame.lambda;
    elements.mu[e] = lame.mu;
    elements.density[e] = material.density;
    elements.wave_speed[e] = std::sqrt((lame.lambda + 2 * lame.mu) / material.density);

    double mass[24 * 24];
    hex8_mass(x, material.density, true, mass);
    double masses[8];
    for (int a = 0; a < 8; ++a)
      masses[a] = mass[(3 * a) * 24 + 3 * a];

    double* gradient = &elements.gradients[24 * static_cast<std::size_t>(e) * n_points];
    double hourglass_omega2 = 0;
    if (settings.full_integration) {
      double volume = 0;
      for (int q = 0; q < 8; ++q) {
        double g[3][8];
        const double det = hex8_gradients(x, table.dN[q], g);
        elements.weights[8 * e + q] = det;
        volume += det;
        for (int i = 0; i < 3; ++i)
          std::copy_n(g[i], 8, gradient + 24 * q + 8 * i);
      }
      elements.volume[e] = volume;
    } else {
      const double volume = hex8_mean_gradients(x, gradient);
      elements.volume[e] = volume;
      double* projection = &elements.hourglass_projection[12 * static_cast<std::size_t>(e)];
      hex8_hourglass_projections(x, projection);
      double gamma[32];
      hex8_hourglass_vectors(projection, gradient, gamma);
      const double kappa = settings.hourglass_coefficient;
      double stiffness = 0;
      if (settings.hourglass == HourglassForm::stiffness) {
        stiffness = hex8_hourglass_stiffness(gradient, volume, lame, kappa);
        elements.hourglass_scale[e] = stiffness;
      } else if (settings.hourglass == HourglassForm::viscous) {
        elements.hourglass_scale[e] =
            kappa * material.density * elements.wave_speed[e] * std::cbrt(volume * volume) / 4;
      }
      if (stiffness > 0)
        hourglass_omega2 = hourglass_frequency_squared(gamma, masses, stiffness);
    }
    // L / c_P: the period of the mesh's highest (checkerboard) mode on uniform meshes.
    elements.length[e] = elements.volume[e] / largest_face_area(x);
    elements.stable_step[e] = elements.length[e] / elements.wave_speed[e];
    if (hourglass_omega2 > 0)
      elements.stable_step[e] = std::min(elements.stable_step[e], 2 / std::sqrt(hourglass_omega2));
  }
  return elements;
}

std::string solid_kernel_name(const SolidKernelSettings& settings) {
  if (settings.full_integration)
    return "scalar (full integration)";
  if (!settings.batched)
    return "scalar";
  switch (batched_kernel_lanes()) {
    case 8:
      return "batched, 8 lanes (AVX-512)";
    case 4:
      return "batched, 4 lanes (AVX2)";
    default:
      return "scalar (this CPU has neither AVX-512 nor AVX2)";
  }
}

SolidForceTotals add_internal_forces(const SolidElements& elements,
                                     const SolidKernelSettings& settings, const double* coordinates,
                                     const double* u, const double* v, double* forces) {
  const int lanes = batched_kernel_lanes();
  if (settings.batched && elements.n_points == 1 && lanes > 0)
    return add_internal_forces_batched(elements, settings, coordinates, u, v, forces, lanes);
  SolidForceTotals totals;
  double strain = 0, hourglass_energy = 0, hourglass_power = 0, viscous_power = 0;
  const int n_points = elements.n_points;
  const bool stiffness_form = settings.hourglass == HourglassForm::stiffness;
  const bool hourglass = !settings.full_integration && settings.hourglass != HourglassForm::none;
  for (LocalIndex e = 0; e < elements.n_elements; ++e) {
    const LocalIndex* nodes = &elements.nodes[8 * static_cast<std::size_t>(e)];
    double ue[8][3], ve[8][3], xe[8][3], fe[8][3] = {};
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i) {
        const std::size_t k = 3 * static_cast<std::size_t>(nodes[a]) + i;
        ue[a][i] = u[k];
        ve[a][i] = v[k];
        xe[a][i] = coordinates[k] + u[k];
      }
    const SolidElementConstants<double> constants{elements.lambda[e], elements.mu[e],
                                                  elements.density[e], elements.wave_speed[e],
                                                  elements.length[e]};
    double volume = 0, compression = 0;
    const double* gradient = &elements.gradients[24 * static_cast<std::size_t>(e) * n_points];
    for (int q = 0; q < n_points; ++q) {
      double jacobian = 1, div = 0;
      const double w = n_points == 1 ? elements.volume[e]
                                     : elements.weights[static_cast<std::size_t>(e) * n_points + q];
      strain += add_point_forces(gradient + 24 * q, w, ue, ve, constants, settings, fe,
                                 viscous_power, jacobian, div);
      volume += jacobian * w;
      compression = std::min(compression, div);
    }
    // Current characteristic length: current volume over the largest current face.
    const double length = volume / largest_face_area(xe);
    if (hourglass) {
      double gamma[32];
      hex8_hourglass_vectors(&elements.hourglass_projection[12 * static_cast<std::size_t>(e)],
                             gradient, gamma);
      add_hourglass_forces(gamma, elements.hourglass_scale[e], stiffness_form ? ue : ve,
                           stiffness_form, fe, hourglass_energy, hourglass_power);
    }
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i)
        forces[3 * static_cast<std::size_t>(nodes[a]) + i] += fe[a][i];

    const double step = current_stable_step(elements.stable_step[e], elements.length[e], length,
                                            compression, elements.wave_speed[e], settings);
    if (step < totals.stable_step) {
      totals.stable_step = step;
      totals.critical_element = e;
    }
  }
  totals.strain_energy = strain;
  totals.hourglass_energy = hourglass_energy;
  totals.hourglass_power = hourglass_power;
  totals.viscous_power = viscous_power;
  return totals;
}

std::pair<double, std::string> smallest_step(const SolidElements& elements,
                                             const MeshPartition& partition,
                                             const std::vector<double>& step,
                                             const double* coordinates) {
  const Communicator& comm = partition.comm();
  LocalIndex critical = -1;
  double local = 1e300;
  for (LocalIndex e = 0; e < elements.n_elements; ++e) {
    if (step[e] < local) {
      local = step[e];
      critical = e;
    }
  }
  const double global = comm.min(local);
  std::vector<double> where;
  if (critical >= 0 && local == global) {
    double centre[3] = {0, 0, 0};
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d)
        centre[d] +=
            coordinates[3 * static_cast<std::size_t>(elements.nodes[8 * critical + a]) + d] / 8;
    where = {static_cast<double>(elements.global_element[critical]), centre[0], centre[1],
             centre[2]};
  }
  std::vector<double> first = comm.gather_to_root(where);
  first.resize(4, 0.0);
  comm.broadcast(first);
  const Mesh& mesh = partition.mesh();
  const auto element = static_cast<GlobalIndex>(first[0]);
  std::ostringstream text;
  text << "element " << element + 1 << " of block '" << mesh.blocks[mesh.block_of(element)].name
       << "' at (" << first[1] << ", " << first[2] << ", " << first[3] << ") m";
  return {global, text.str()};
}

void hourglass_vectors(const SolidElements& elements, LocalIndex e, double gamma[32]) {
  hex8_hourglass_vectors(&elements.hourglass_projection[12 * static_cast<std::size_t>(e)],
                         &elements.gradients[24 * static_cast<std::size_t>(e)], gamma);
}

void element_cauchy_stress(const SolidElements& elements, LocalIndex e, const double* u,
                           double stress[6]) {
  std::fill(stress, stress + 6, 0.0);
  const LocalIndex* nodes = &elements.nodes[8 * static_cast<std::size_t>(e)];
  const int n_points = elements.n_points;
  for (int q = 0; q < n_points; ++q) {
    const double* g = &elements.gradients[24 * (static_cast<std::size_t>(e) * n_points + q)];
    double F[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int a = 0; a < 8; ++a)
          F[i][j] += u[3 * static_cast<std::size_t>(nodes[a]) + i] * g[j * 8 + a];
    Eigen::Matrix3d Fm;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        Fm(i, j) = F[i][j];
    const Eigen::Matrix3d E = 0.5 * (Fm.transpose() * Fm - Eigen::Matrix3d::Identity());
    const Eigen::Matrix3d S =
        elements.lambda[e] * E.trace() * Eigen::Matrix3d::Identity() + 2 * elements.mu[e] * E;
    const Eigen::Matrix3d sigma = Fm * S * Fm.transpose() / Fm.determinant();
    const double values[6] = {sigma(0, 0), sigma(1, 1), sigma(2, 2),
                              sigma(0, 1), sigma(1, 2), sigma(2, 0)};
    for (int k = 0; k < 6; ++k)
      stress[k] += values[k] / n_points;
  }
}

}  // namespace railfe
