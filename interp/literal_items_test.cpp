// A block's literal runs (ast::LiteralRun) read through the evaluator: the same values,
// locations and errors as the same text read one node per value.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using LiteralItems = BuildTest;

// A mesh2 with `n` vertices on a line, faces between consecutive ones; `index` replaces the
// last face's last index. Written `<a+0, ...>`, no vertex is a literal and no run forms.
std::string mesh(int n, bool literal, const std::string& index = "") {
    std::string s = "mesh2 {\n  vertex_vectors { " + std::to_string(n);
    for (int i = 0; i < n; ++i)
        s += literal ? ",\n    <" + std::to_string(i) + ", " + std::to_string(i % 3) + ", -0.5>"
                     : ",\n    <" + std::to_string(i) + "+0, " + std::to_string(i % 3) + ", -0.5>";
    s += " }\n  face_indices { " + std::to_string(n - 2);
    for (int i = 0; i + 2 < n; ++i) {
        const std::string last = i + 3 == n && !index.empty() ? index : std::to_string(i + 2);
        s += literal ? ", <" + std::to_string(i) + "," + std::to_string(i + 1) + "," + last + ">"
                     : ", <" + std::to_string(i) + "+0," + std::to_string(i + 1) + "," + last + ">";
    }
    return s + " }\n}\n";
}

TEST_F(LiteralItems, ARunBuildsWhatTheSameValuesWrittenOneByOneBuild) {
    const std::string runs = dump_scene_json(run(mesh(12, true)));
    EXPECT_EQ(runs, dump_scene_json(run(mesh(12, false))));
    EXPECT_NE(runs, dump_scene_json(run(mesh(13, true))));  // the dump does show the mesh
}

TEST_F(LiteralItems, ErrorsPointAtTheElement) {
    // The last face's index 12 is out of range: the error is where that face is written.
    const std::string text = mesh(12, true, "12");
    const size_t face = text.find("<9,10,12>");
    const size_t line_start = text.rfind('\n', face) + 1;
    const int line = int(std::count(text.begin(), text.begin() + std::ptrdiff_t(face), '\n')) + 1;
    EXPECT_EQ(error_of(text), "t.pov:" + std::to_string(line) + ":" +
                                  std::to_string(face - line_start + 1) +
                                  ": error: vertex index 12 out of range (there are 12)");
    // Read from nodes, the same error.
    EXPECT_NE(error_of(mesh(12, false, "12")).find("vertex index 12 out of range"), std::string::npos);
}

TEST_F(LiteralItems, RunsFromMacrosAndIncludesAreReadInPlace) {
    // A macro body's run, and an include file's, splice into the block where they are used,
    // as their items did.
    const std::string verts = "<0,0,0>, <1,0,0>, <0,1,0>, <1,1,0>, <0,0,1>, <1,0,1>, <0,1,1>, <1,1,1>";
    const std::string faces = " } face_indices { 2, <0,1,2>, <5,6,7> } }";
    const std::string inline_mesh = dump_scene_json(run("\nmesh2 { vertex_vectors { 8, " + verts + faces));
    EXPECT_NE(inline_mesh.find("[1, 1, 1]"), std::string::npos);
    EXPECT_EQ(dump_scene_json(run("#macro Verts() " + verts + " #end\n"
                                  "mesh2 { vertex_vectors { 8, Verts()" + faces)),
              inline_mesh);
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("lumen_runs_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "verts.inc") << verts;
    options.library_paths = {dir.string()};
    const std::string included = dump_scene_json(
        run("\nmesh2 { vertex_vectors { 8,\n#include \"verts.inc\"\n" + faces));
    std::filesystem::remove_all(dir);
    EXPECT_EQ(included, inline_mesh);
}

TEST_F(LiteralItems, CountedReadersSeeEveryElement) {
    // A macro used as a value must produce one item: 15 here, as without runs.
    EXPECT_EQ(error_of("#macro L() 1,2,3,4,5,6,7,8 #end\n#declare X = L();"),
              "t.pov:2:14: error: macro 'L' used in an expression produced 15 items");
    // Top level: the first float is unexpected, where it is written.
    EXPECT_EQ(error_of("\n  1,2,3,4,5,6,7,8,9"), "t.pov:2:3: error: a float cannot stand at top level");
}

}  // namespace
}  // namespace lumen::interp::testing
