// #fopen / #write / #read / #fclose against POV-Ray 3.7: the expected bytes and values are
// what povray wrote and read for the same directives.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "interp/eval_test_support.hpp"

namespace lumen::interp::testing {
namespace {
namespace fs = std::filesystem;

// Runs each test in a fresh working folder (where #write puts files).
class FileIoTest : public EvalTest {
protected:
    void SetUp() override {
        previous_ = fs::current_path();
        dir_ = fs::temp_directory_path() / ("lumen_fileio_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "work");
        fs::current_path(dir_ / "work");
    }
    void TearDown() override {
        fs::current_path(previous_);
        fs::remove_all(dir_);
    }
    static std::string contents(const std::string& name) {
        std::ifstream in(name, std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }
    std::vector<std::string> notes() const {
        std::vector<std::string> out;
        for (const Diagnostic& d : messages) out.push_back(d.message);
        return out;
    }
    fs::path previous_, dir_;
};

TEST_F(FileIoTest, WritesPovRayFormats) {
    run("#fopen F \"out.txt\" write\n"
        "#write (F, \"a\\tb\", 1/3, 1e-7, 123456789, 1e6, 5 6 7, <1,2,3>, <1.5,2>, <1,2,3,4>, \"\\n\")\n"
        "#write (F \"x\" \"y\" -2.5 \"\\n\")\n"
        "#fclose F\n#fclose F\n"
        "#fopen A \"out.txt\" append\n#write (A, \"appended\\n\")\n#fclose A\n"
        "#fopen B \"bytes.bin\" write\n"
        "#write (B, uint8 <65,66.4,66.6,300,-5>, sint8 -129, uint16le 513, uint16be 513, "
        "sint16le -2, sint16be -2, sint32le -70000, sint32be 70000)\n#fclose B\n");
    EXPECT_EQ(contents("out.txt"),
              "a\tb0.3333331e-071.23457e+081e+06567<1,2,3> <1.5,2> <1,2,3,4> \nxy-2.5\nappended\n");
    EXPECT_EQ(contents("bytes.bin"),
              std::string("ABC\xff\0\x80\x01\x02\x02\x01\xfe\xff\xff\xfe\x90\xee\xfe\xff\0\x01\x11p",
                          22));
}

TEST_F(FileIoTest, DirectivesAmongWriteValuesWriteWhatTheyLeave) {
    run("#fopen F \"o.txt\" write\n"
        "#write(F, \"a\", #for (I, 1, 3) \",\", I #end, #if (0) \"no\" #else \"x\" #end)\n"
        "#fclose F\n");
    EXPECT_EQ(contents("o.txt"), "a,1,2,3x");
}

// shapes.inc's HF_Square with a file name writes its mesh2 with #write arguments that run
// through #while loops and #if branches: the bytes povray 3.7 wrote for the same call.
TEST_F(FileIoTest, ShapesIncWritesTheMeshPovRayWrites) {
    run("#include \"shapes.inc\"\n"
        "#declare Fn = function(x, y, z) { 0.5 + 0.25 * x }\n"
        "HF_Square(Fn, 1, 1, <3, 2>, 1, \"sq.inc\", <0, 0, 0>, <1, 1, 1>)\n");
    EXPECT_EQ(contents("sq.inc"),
              "mesh2 {\nvertex_vectors {\n6,\n<0,0.5,0> ,\n<0,0.5,1> ,\n<0.5,0.625,0> ,\n"
              "<0.5,0.625,1> ,\n<1,0.75,0> ,\n<1,0.75,1> \n}\nnormal_vectors {\n6,\n"
              "<-0.242536,0.970143,0> ,\n<-0.242536,0.970143,0> ,\n<-0.242536,0.970143,0> ,\n"
              "<-0.242536,0.970143,0> ,\n<-0.242536,0.970143,0> ,\n<-0.242536,0.970143,0> \n}\n"
              "uv_vectors {\n6,\n<0,0> ,\n<0,1> ,\n<0.5,0> ,\n<0.5,1> ,\n<1,0> ,\n<1,1> \n}\n"
              "face_indices {\n4,\n<0,2,3> ,\n<0,3,1> ,\n<2,4,5> ,\n<2,5,3> \n}\nuv_mapping\n}");
}

TEST_F(FileIoTest, ReadsCommaSeparatedLiteralsAndClosesAtTheEnd) {
    std::ofstream("data.txt") << "\"hello\", 1.5, <1,2,3>, -4,\n<5,6>, 7 8 9, 10";
    run("#declare R = array[9];\n#fopen D \"data.txt\" read\n#declare N = 0;\n"
        "#while (defined(D)) #read (D, V) #declare N = N + 1; #declare R[N] = V; #undef V #end\n");
    EXPECT_DOUBLE_EQ(num_var("N"), 8);  // "8" is lost after 7 (no comma), as in POV-Ray
    const auto& r = *var("R").as<std::shared_ptr<ArrayValue>>();
    EXPECT_EQ(r.elems[1]->as<std::string>(), "hello");
    EXPECT_DOUBLE_EQ(r.elems[2]->as<double>(), 1.5);
    EXPECT_EQ(components(*r.elems[3]), (std::vector<double>{1, 2, 3}));
    EXPECT_DOUBLE_EQ(r.elems[4]->as<double>(), -4);
    EXPECT_EQ(components(*r.elems[5]), (std::vector<double>{5, 6}));
    EXPECT_DOUBLE_EQ(r.elems[6]->as<double>(), 7);
    EXPECT_DOUBLE_EQ(r.elems[7]->as<double>(), 9);
    EXPECT_DOUBLE_EQ(r.elems[8]->as<double>(), 10);
}

TEST_F(FileIoTest, AFileWrittenAgainIsIncludedAfresh) {
    run("#fopen I \"inc.inc\" write #write (I, \"#declare Included = 17;\") #fclose I\n"
        "#include \"inc.inc\" #declare First = Included;\n"
        "#fopen I \"inc.inc\" write #write (I, \"#declare Included = 18;\") #fclose I\n"
        "#include \"inc.inc\"\n");
    EXPECT_DOUBLE_EQ(num_var("First"), 17);
    EXPECT_DOUBLE_EQ(num_var("Included"), 18);
}

TEST_F(FileIoTest, LocatedErrors) {
    const std::string write_rule =
        "(lumen writes user files only under the working folder, the scene's folder and the "
        "output folder; Permitted_Path=FOLDER allows another)";
    EXPECT_EQ(error_of("#fopen F \"../out.txt\" write"),
              "test.pov:1:10: error: IO Restrictions prohibit write access to '../out.txt' " +
                  write_rule);
    EXPECT_EQ(error_of("#fopen F \"/etc/lumen.txt\" write"),
              "test.pov:1:10: error: IO Restrictions prohibit write access to '/etc/lumen.txt' " +
                  write_rule);
    EXPECT_EQ(error_of("#fopen F \"nope.txt\" read"),
              "test.pov:1:10: error: cannot open user file 'nope.txt' (read)");
    EXPECT_EQ(error_of("#write (G, 1)"), "test.pov:1:9: error: 'G' is not an open file identifier");
    std::ofstream("d.txt") << "<1,2>, 3";
    // POV-Ray refuses to read into a uv vector identifier (the first read made V one).
    EXPECT_EQ(error_of("#fopen D \"d.txt\" read #read (D, V) #read (D, V)"),
              "test.pov:1:46: error: #read into 'V': expected an undeclared identifier or a "
              "float, 3-D vector or string one, found a 2-component vector");
    EXPECT_EQ(error_of("#fopen F \"o.txt\" write #write (F, rgb 1)"),
              "test.pov:1:35: error: expected a string, float or vector, found a colour");
}

// Reading is refused outside the working folder, the permitted folders and the include
// folders; a symbolic link cannot lead out; Permitted_Path (io_folders) opens a folder.
TEST_F(FileIoTest, OnlyPermittedFoldersAreOpened) {
    fs::create_directories(dir_ / "other");
    std::ofstream(dir_ / "other" / "in.txt") << "5";
    const std::string in = (dir_ / "other" / "in.txt").string();
    const std::string out = (dir_ / "other" / "out.txt").string();
    EXPECT_NE(error_of("#fopen D \"" + in + "\" read").find(
                  "IO Restrictions prohibit read access to '" + in +
                  "' (lumen reads user files only under the working folder, the scene's folder, "
                  "the output folder and the library paths; Permitted_Path=FOLDER allows another)"),
              std::string::npos);
    fs::create_directory_symlink(dir_ / "other", "link");
    EXPECT_NE(error_of("#fopen F \"link/out.txt\" write").find("prohibit write access"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(out));
    options.io_folders.push_back((dir_ / "other").string());
    ev.reset();
    run("#fopen D \"" + in + "\" read #read (D, V)\n#fopen F \"link/out.txt\" write #write (F, V) "
        "#fclose F\n");
    EXPECT_DOUBLE_EQ(num_var("V"), 5);
    EXPECT_EQ(contents(out), "5");
}

}  // namespace
}  // namespace lumen::interp::testing
