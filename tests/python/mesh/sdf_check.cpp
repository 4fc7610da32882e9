// Load an SDF file with Gazebo's own parser, libsdformat (Debian's libsdformat-dev,
// sdformat 12), and print what tests/python/mesh/test_mesh_gazebo.py checks, one
// tab-separated record a line:
//
//   error  <message>                  every error the parser reports
//   world  <name>                     each world, then its models
//   model  <name>                     the file's model, or a world's (an <include>d one)
//   link   <name>  <mass>
//   mesh   collision|visual  <uri>  <file the uri resolves to, empty if none>
//   errors <count>
//
// Usage: sdf_check FILE [SCHEME=FOLDER ...], e.g. model://=tools/hook_new1/gazebo: a
// URI scheme and a folder searched for its URIs (as Gazebo's resource path is for
// model://). FILE is SDF, or URDF (libsdformat converts it).
#include <iostream>
#include <string>

#include <sdf/sdf.hh>

static void print_geometry(const sdf::Geometry *geometry, const char *element,
                           const sdf::ParserConfig &config) {
  if (geometry != nullptr && geometry->Type() == sdf::GeometryType::MESH) {
    const std::string uri = geometry->MeshShape()->Uri();
    std::cout << "mesh\t" << element << "\t" << uri << "\t"
              << sdf::findFile(uri, false, false, config) << "\n";
  }
}

static void print_model(const sdf::Model *model, const sdf::ParserConfig &config) {
  std::cout << "model\t" << model->Name() << "\n";
  for (uint64_t i = 0; i < model->LinkCount(); ++i) {
    const sdf::Link *link = model->LinkByIndex(i);
    std::cout << "link\t" << link->Name() << "\t" << link->Inertial().MassMatrix().Mass()
              << "\n";
    for (uint64_t j = 0; j < link->CollisionCount(); ++j)
      print_geometry(link->CollisionByIndex(j)->Geom(), "collision", config);
    for (uint64_t j = 0; j < link->VisualCount(); ++j)
      print_geometry(link->VisualByIndex(j)->Geom(), "visual", config);
  }
}

int main(int argc, char **argv) {
  if (argc < 2) {
    std::cerr << "usage: sdf_check FILE [SCHEME=FOLDER ...]\n";
    return 2;
  }
  sdf::ParserConfig config;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    const std::size_t eq = arg.find('=');
    if (eq == std::string::npos) {
      std::cerr << "sdf_check: " << arg << ": not SCHEME=FOLDER\n";
      return 2;
    }
    config.AddURIPath(arg.substr(0, eq), arg.substr(eq + 1));
  }
  sdf::Root root;
  const sdf::Errors errors = root.Load(argv[1], config);
  for (const auto &e : errors) std::cout << "error\t" << e.Message() << "\n";
  if (root.Model() != nullptr) print_model(root.Model(), config);
  for (uint64_t w = 0; w < root.WorldCount(); ++w) {
    const sdf::World *world = root.WorldByIndex(w);
    std::cout << "world\t" << world->Name() << "\n";
    for (uint64_t i = 0; i < world->ModelCount(); ++i)
      print_model(world->ModelByIndex(i), config);
  }
  std::cout << "errors\t" << errors.size() << "\n";
  return 0;
}
