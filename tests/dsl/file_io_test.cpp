// SPDX-License-Identifier: MIT
// #fopen, #write, #read and #fclose: data files a scene writes stay in memory for the rest of
// the read, so reading a scene never writes to the disk.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

dsl::Vector3 centre(const dsl::SceneDescription& d, std::size_t i = 0) {
    return std::get<dsl::SphereShape>(d.objects.at(i).shape).center;
}

}  // namespace

TEST_CASE("#write then #read gives back strings, floats and vectors, as in POV-Ray's fileio.pov", "[dsl][fileio]") {
    const std::string name = "photon_test_never_written.txt";
    const auto p = parse("#fopen F \"" + name + "\" write\n"
                         "#write (F, \"\\\"Testing 123\\\",\", 5, \",\", <1, 2, 3>, \"\\n\")\n"
                         "#fclose F\n"
                         "#fopen F \"" + name + "\" read\n"
                         "#read (F, S, N, V)\n"
                         "#ifdef (F) #error \"the file should be undefined after its last item\" #end\n"
                         "sphere { V * N, 1 }\n");
    CHECK(centre(p.desc) == dsl::Vector3(5, 10, 15));
    CHECK_FALSE(std::filesystem::exists(name));  // in memory only
}

TEST_CASE("#read in a loop until the file is undefined: #include of a written file", "[dsl][fileio]") {
    const auto p = parse("#fopen F \"data.txt\" write\n"
                         "#write (F, 1, \",\", 2, \",\", 3)\n"
                         "#fclose F\n"
                         "#declare Sum = 0;\n"
                         "#fopen F \"data.txt\" read\n"
                         "#while (defined(F)) #read (F, A) #declare Sum = Sum + A; #end\n"
                         "#fopen G \"made.inc\" write\n"
                         "#write (G, \"sphere { <\", Sum, \", 0, 0>, 1 }\")\n"
                         "#fclose G\n"
                         "#include \"made.inc\"\n");
    CHECK(centre(p.desc) == dsl::Vector3(6, 0, 0));
}

TEST_CASE("data-file errors are located", "[dsl][fileio]") {
    CHECK_THROWS_WITH(parse("#fopen F \"nowhere.txt\" read\n"), Contains("1:10: error: cannot find the data file"));
    CHECK_THROWS_WITH(parse("#fopen F \"a.txt\" sideways\n"), Contains("1:18: error: expected `read`, `write`"));
    CHECK_THROWS_WITH(parse("#read (G, A)\n"), Contains("1:8: error: expected a file opened with `#fopen`"));
    CHECK_THROWS_WITH(parse("#fopen F \"a.txt\" write\n#write (F, uint8 3)\n"),
                      Contains("2:12: error: binary `#write` (`uint8`) is not supported"));
    CHECK_THROWS_WITH(parse("#fopen F \"a.txt\" write\n#write (F, \"x y\")\n#fclose F\n#fopen F \"a.txt\" read\n#read (F, A)\n"),
                      Contains("5:11: error: #read: expected a number, a vector or a string"));
}
