// Output of the modal step: classification of the gathered mode shapes, modes CSV, Exodus mode
// shapes, validation table, Matrix Market export and the chart.
#include <MatrixMarket_Tpetra.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "framework/base/error.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/output/exodus_writer.hpp"
#include "framework/output/field_gather.hpp"
#include "physics/common/chart_script.hpp"
#include "physics/modal/modal_step.hpp"

namespace railfe {

namespace {

// The owned nodes' translations (node-major, 3 per node) of column \p j over \p dofs.
std::vector<double> owned_nodal_values(const DofMap& dofs, const TpetraMultiVector& modes,
                                       std::size_t j) {
  const auto data = modes.getData(j);
  std::vector<double> values(3 * static_cast<std::size_t>(dofs.partition().n_owned_nodes()));
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = data[dofs.local_dof(static_cast<LocalIndex>(i / 3), static_cast<int>(i % 3))];
  return values;
}

const char* kFamilies[] = {"axial", "radial", "circumferential", "ambiguous"};

double family_code(const std::string& family) {
  for (int k = 0; k < 4; ++k) {
    if (family == kFamilies[k])
      return k;
  }
  return 3;
}

std::string shape_label(const ModeClass& shape) {
  if (shape.family.empty())
    return "";
  return shape.family;
}

}  // namespace

void ModalStep::classify(const DofMap& dofs, const TpetraMultiVector& modes,
                         std::vector<ModeRecord>& records) const {
  const MeshPartition& partition = dofs.partition();
  const Mesh& mesh = partition.mesh();
  const Communicator& comm = partition.comm();
  std::vector<GlobalIndex> nodes;  // nodes of the solid (others carry no displacement)
  std::vector<std::array<double, 3>> points;
  for (GlobalIndex node = 0; node < mesh.n_nodes(); ++node) {
    if (partition.node_ranks()[node] < 0)
      continue;
    nodes.push_back(node);
    points.push_back(mesh.node(node));
  }
  std::vector<double> packed;  // per mode: family, n, m, shares ×4, phase
  std::vector<std::string> notes;
  for (std::size_t j = 0; j < records.size(); ++j) {
    const auto field = gather_node_field(partition, owned_nodal_values(dofs, modes, j), 3);
    if (!comm.is_root())
      continue;
    std::vector<std::array<double, 3>> displacements(nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      for (int d = 0; d < 3; ++d)
        displacements[k][d] = field[d][nodes[k]];
    }
    const ModeClass shape = classify_mode(points, displacements, frame_, classifier_);
    packed.insert(packed.end(),
                  {family_code(shape.family), double(shape.nodal_diameters),
                   double(shape.nodal_circles), shape.diameter_share, shape.axial_share,
                   shape.radial_share, shape.circumferential_share, shape.phase_angle});
    notes.push_back(shape.note);
  }
  // Every rank needs the labels: they decide which modes fail the doublet check.
  comm.broadcast(packed);
  for (std::size_t j = 0; j < records.size(); ++j) {
    ModeClass& shape = records[j].shape;
    const double* v = &packed[8 * j];
    shape.family = kFamilies[static_cast<int>(v[0])];
    shape.nodal_diameters = static_cast<int>(v[1]);
    shape.nodal_circles = static_cast<int>(v[2]);
    shape.diameter_share = v[3];
    shape.axial_share = v[4];
    shape.radial_share = v[5];
    shape.circumferential_share = v[6];
    shape.phase_angle = v[7];
    std::string note = comm.is_root() ? notes[j] : std::string();
    comm.broadcast(note);
    shape.note = note;
  }
}

void ModalStep::write_results(StepContext& context, const DofMap& dofs,
                              const std::vector<ModeRecord>& records,
                              const TpetraMultiVector* modes) const {
  const MeshPartition& partition = dofs.partition();
  const bool root = partition.comm().is_root();
  const std::string& name = context.step_name;
  const std::string csv_path = context.output.staging_path(name + "_modes.csv");
  {
    CsvWriter csv(csv_path,
                  {"mode", "frequency_hz", "eigenvalue_rad2_per_s2", "family", "nodal_diameters",
                   "nodal_circles", "partner", "modal_mass_kg", "effective_mass_x_kg",
                   "effective_mass_y_kg", "effective_mass_z_kg", "backward_error", "orthogonality",
                   "diameter_share", "status", "note"},
                  root);
    for (std::size_t i = 0; i < records.size(); ++i) {
      const ModeRecord& r = records[i];
      const bool classified = classify_;
      csv.write_row(
          {std::to_string(i + 1), CsvWriter::format(r.frequency), CsvWriter::format(r.eigenvalue),
           classified ? shape_label(r.shape) : "",
           classified ? std::to_string(r.shape.nodal_diameters) : "",
           classified ? std::to_string(r.shape.nodal_circles) : "",
           r.check.partner >= 0 ? std::to_string(r.check.partner + 1) : "",
           CsvWriter::format(r.check.modal_mass), CsvWriter::format(r.check.effective_mass[0]),
           CsvWriter::format(r.check.effective_mass[1]),
           CsvWriter::format(r.check.effective_mass[2]), CsvWriter::format(r.check.backward_error),
           CsvWriter::format(r.check.orthogonality),
           classified ? CsvWriter::format(r.shape.diameter_share) : "", r.status, r.shape.note});
    }
  }
  if (classify_ && parameters_->get<bool>("Chart") && !records.empty())
    draw_chart(context, csv_path);

  if (!parameters_->get<bool>("Exodus") || modes == nullptr)
    return;
  // One output time per mode (time = mode number), so ParaView steps through the modes and its
  // Exodus reader can animate each one ("Animate Vibrations"). The whole mesh is written: blocks
  // left out by Blocks stand still beside the modes (their nodes carry no unknowns: zeros).
  ExodusWriter writer(context.output.staging_path(name + ".exo"), context.model.mesh(),
                      context.model.deck().parameters->get<std::string>("Title"),
                      {"displacement_x", "displacement_y", "displacement_z"}, {}, root);
  for (std::size_t j = 0; j < records.size(); ++j) {
    const auto field = gather_node_field(partition, owned_nodal_values(dofs, *modes, j), 3);
    writer.write_step(static_cast<double>(j + 1), field, {});
  }
  writer.close();
}

void ModalStep::write_validation(StepContext& context,
                                 const std::vector<ModeRecord>& records) const {
  const bool root = context.model.comm().is_root();
  CsvWriter csv(context.output.staging_path(context.step_name + "_validation.csv"),
                {"reference", "family", "nodal_circles", "nodal_diameters", "reference_hz",
                 "computed_hz", "difference_percent", "mode"},
                root);
  for (const auto& reference : references_) {
    int found = -1;
    for (std::size_t i = 0; i < records.size() && found < 0; ++i) {
      const ModeClass& shape = records[i].shape;
      if (shape.family == reference.family && shape.nodal_circles == reference.nodal_circles &&
          shape.nodal_diameters == reference.nodal_diameters)
        found = static_cast<int>(i);
    }
    std::vector<std::string> row{
        reference.name, reference.family, std::to_string(reference.nodal_circles),
        std::to_string(reference.nodal_diameters), CsvWriter::format(reference.frequency)};
    if (found >= 0) {
      const double computed = records[found].frequency;
      row.push_back(CsvWriter::format(computed));
      row.push_back(
          CsvWriter::format(100.0 * (computed - reference.frequency) / reference.frequency));
      row.push_back(std::to_string(found + 1));
    } else {
      row.insert(row.end(), {"", "", "not found"});
    }
    csv.write_row(row);
    context.summary.add("Step " + context.step_name + " (modal): validation",
                        reference.name + " (" + reference.family + " " +
                            std::to_string(reference.nodal_circles) + "," +
                            std::to_string(reference.nodal_diameters) + ") Hz",
                        found >= 0 ? CsvWriter::format(records[found].frequency) + " computed, " +
                                         CsvWriter::format(reference.frequency) + " reference"
                                   : std::string("not found"));
  }
}

void ModalStep::export_matrices(StepContext& context, const TpetraMatrix& K,
                                const TpetraMatrix& M) {
  using Writer = Tpetra::MatrixMarket::Writer<TpetraMatrix>;
  const std::string& name = context.step_name;
  Writer::writeSparseFile(context.output.staging_path(name + "_K.mtx"), K, "K",
                          "railfe stiffness (prescribed DOFs: unit rows)");
  Writer::writeSparseFile(context.output.staging_path(name + "_M.mtx"), M, "M",
                          "railfe mass (prescribed DOFs: zero rows)");
}

void ModalStep::draw_chart(StepContext& context, const std::string& csv_path) const {
  const std::string png = context.output.staging_path(context.step_name + "_modes.png");
  railfe::draw_chart(context, "Step " + context.step_name + " (modal)", "mode_chart.py",
                     {csv_path, png});
}

}  // namespace railfe
