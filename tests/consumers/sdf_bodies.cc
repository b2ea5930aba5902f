// Reads an SDFormat file with libsdformat (Gazebo's own parser) and prints every link's
// inertial as JSON, in the convention of tests/python/robot_bodies.py: mass (kg), centre of
// mass (m, link frame), tensor about it (kg*m^2, link axes, off-diagonals -sum(m*x*y)), and
// the link's pose in the top model's frame (a world's: its models' links scoped by model). Names of nested models' links are scoped
// (outer::link), and each visual's mesh (URI, scale, pose in the link frame). Usage: sdf_bodies FILE [MODELS_DIR] (MODELS_DIR is where model://NAME is).
#include <sdf/sdf.hh>

#include <cstdio>
#include <iostream>
#include <string>

namespace {

using ignition::math::Matrix3d;
using ignition::math::Pose3d;

// X_OQ from X_OP and X_PQ, written out (ign-math 6's Pose3 operator* composes the other way).
Pose3d Compose(const Pose3d &op, const Pose3d &pq) {
  return Pose3d(op.Pos() + op.Rot().RotateVector(pq.Pos()), op.Rot() * pq.Rot());
}

void PrintMatrix(const Matrix3d &m) {
  std::printf("[");
  for (int r = 0; r < 3; ++r) {
    std::printf("%s[%.17g, %.17g, %.17g]", r ? ", " : "", m(r, 0), m(r, 1), m(r, 2));
  }
  std::printf("]");
}

bool first = true;

bool Visit(const sdf::Model *model, const std::string &prefix, const Pose3d &x_top_model) {
  for (uint64_t i = 0; i < model->LinkCount(); ++i) {
    const sdf::Link *link = model->LinkByIndex(i);
    Pose3d x_model_link;
    sdf::Errors errors = link->SemanticPose().Resolve(x_model_link);
    if (!errors.empty()) {
      std::cerr << "link " << link->Name() << ": " << errors[0].Message() << "\n";
      return false;
    }
    const Pose3d x = Compose(x_top_model, x_model_link);
    const ignition::math::Inertiald &inertial = link->Inertial();
    const Matrix3d r(inertial.Pose().Rot());
    const Matrix3d tensor = r * inertial.MassMatrix().Moi() * r.Transposed();
    const auto &c = inertial.Pose().Pos();
    std::printf("%s\"%s%s\": {\"mass\": %.17g, \"com\": [%.17g, %.17g, %.17g], \"tensor\": ",
                first ? "" : ", ", prefix.c_str(), link->Name().c_str(),
                inertial.MassMatrix().Mass(), c.X(), c.Y(), c.Z());
    PrintMatrix(tensor);
    std::printf(", \"position\": [%.17g, %.17g, %.17g], \"rotation\": ", x.Pos().X(),
                x.Pos().Y(), x.Pos().Z());
    PrintMatrix(Matrix3d(x.Rot()));
    // Each visual's mesh: its URI, scale and pose in the link frame.
    std::printf(", \"meshes\": [");
    for (uint64_t v = 0; v < link->VisualCount(); ++v) {
      const sdf::Visual *visual = link->VisualByIndex(v);
      const sdf::Mesh *mesh = visual->Geom()->MeshShape();
      Pose3d x_link_visual;
      visual->SemanticPose().Resolve(x_link_visual);
      std::printf("%s{\"uri\": \"%s\", \"scale\": [%.17g, %.17g, %.17g], \"position\": "
                  "[%.17g, %.17g, %.17g], \"rotation\": ",
                  v ? ", " : "", mesh ? mesh->Uri().c_str() : "",
                  mesh ? mesh->Scale().X() : 0.0, mesh ? mesh->Scale().Y() : 0.0,
                  mesh ? mesh->Scale().Z() : 0.0, x_link_visual.Pos().X(),
                  x_link_visual.Pos().Y(), x_link_visual.Pos().Z());
      PrintMatrix(Matrix3d(x_link_visual.Rot()));
      std::printf("}");
    }
    std::printf("]}");
    first = false;
  }
  for (uint64_t i = 0; i < model->ModelCount(); ++i) {
    const sdf::Model *nested = model->ModelByIndex(i);
    Pose3d x_model_nested;
    sdf::Errors errors = nested->SemanticPose().Resolve(x_model_nested);
    if (!errors.empty()) {
      std::cerr << "model " << nested->Name() << ": " << errors[0].Message() << "\n";
      return false;
    }
    if (!Visit(nested, prefix + nested->Name() + "::", Compose(x_top_model, x_model_nested))) {
      return false;
    }
  }
  return true;
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 2) {
    std::cerr << "usage: sdf_bodies FILE [MODELS_DIR]\n";
    return 2;
  }
  sdf::ParserConfig config;
  if (argc > 2) {
    config.AddURIPath("model://", argv[2]);
  }
  sdf::Root root;
  sdf::Errors errors = root.Load(argv[1], config);
  if (!errors.empty()) {
    for (const auto &e : errors) {
      std::cerr << argv[1] << ": " << e.Message() << "\n";
    }
    return 1;
  }
  std::printf("{\"bodies\": {");
  bool ok = true;
  if (const sdf::Model *model = root.Model()) {
    ok = Visit(model, "", Pose3d::Zero);
  } else if (root.WorldCount() > 0) {
    // A world: each model placed in the world's frame, its links scoped by its name.
    const sdf::World *world = root.WorldByIndex(0);
    for (uint64_t i = 0; ok && i < world->ModelCount(); ++i) {
      const sdf::Model *model = world->ModelByIndex(i);
      Pose3d x_world_model;
      sdf::Errors pose_errors = model->SemanticPose().Resolve(x_world_model);
      ok = pose_errors.empty() && Visit(model, model->Name() + "::", x_world_model);
    }
  } else {
    std::cerr << argv[1] << ": no model\n";
    ok = false;
  }
  std::printf("}}\n");
  return ok ? 0 : 1;
}
