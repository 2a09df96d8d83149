// SPDX-License-Identifier: MIT
// POV-Ray's I/O restrictions (file_access.hpp, povray_conf.hpp): every construct that opens a
// file is refused outside the permitted folders, by an absolute name, by `..` and through a
// symbolic link, with a located error that quotes nothing of the refused file; and the same
// scenes read once the folder is permitted, so that each refusal is the rule's doing.

#include <catch2/catch.hpp>

#include <photon/dsl/povray_conf.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

/// A scene folder and, beside it, a folder the scene may not read, with a secret in it and a
/// symbolic link to it from the scene's folder.
struct Layout {
    ScratchDir dir;
    std::filesystem::path scene_folder, outside;
    static constexpr const char* secret = "SECRET-7f3a-do-not-print";
    Layout() {
        scene_folder = dir.path() / "scene";
        outside = dir.path() / "outside";
        std::filesystem::create_directories(scene_folder);
        for (const char* name : {"secret.inc", "secret.txt", "secret.png", "secret.obj", "secret.ttf"})
            dir.write(std::string("outside/") + name, std::string(secret) + "\n" + secret + "\n");
        std::filesystem::create_directory_symlink(outside, scene_folder / "link");
        std::filesystem::create_symlink(outside / "secret.inc", scene_folder / "linked.inc");
    }
    /// Reads `text` as scene/main.pov; the error's message and its full text, or empty.
    [[nodiscard]] std::pair<std::string, std::string> error(const std::string& text, const dsl::ParseOptions& o = {}) const {
        const auto main = dir.write("scene/main.pov", text);
        try {
            (void)dsl::parse_file(main, o);
        } catch (const dsl::Error& e) {
            return {std::to_string(e.location().line) + ":" + std::to_string(e.location().column) + ": " + e.message(),
                    e.what()};
        }
        return {};
    }
};

/// How each construct names `file`, for a scene that opens it.
std::vector<std::pair<std::string, std::string>> constructs(const std::string& file) {
    const std::string q = "\"" + file + "\"";
    return {
        {"#include", "#include " + q + "\nsphere { 0, 1 }\n"},
        {"#fopen read", "#fopen F " + q + " read\nsphere { 0, 1 }\n"},
        {"image_map", "sphere { 0, 1 pigment { image_map { png " + q + " } } }\n"},
        {"bump_map", "sphere { 0, 1 normal { bump_map { png " + q + " } } }\n"},
        {"height_field", "height_field { png " + q + " }\n"},
        {"mesh obj", "mesh { obj " + q + " }\n"},
        {"text ttf", "text { ttf " + q + " \"A\" 1, 0 }\n"},
    };
}

}  // namespace

TEST_CASE("a permitted folder covers its own files, and its subfolders' with `*`", "[dsl][file_access]") {
    const dsl::PermittedFolder exact{"/srv/scenes", false, false, "test"};
    CHECK(exact.covers("/srv/scenes/a.inc"));
    CHECK_FALSE(exact.covers("/srv/scenes/maps/a.png"));
    CHECK_FALSE(exact.covers("/srv/scenes2/a.inc"));  // components, not characters
    CHECK_FALSE(exact.covers("/srv/a.inc"));
    const dsl::PermittedFolder below{"/srv/scenes", true, false, "test"};
    CHECK(below.covers("/srv/scenes/maps/deep/a.png"));
    CHECK_FALSE(below.covers("/srv/other/a.png"));

    dsl::FileAccessRules rules;
    rules.permit("/srv/scenes", true, false, "read*");
    rules.permit("/srv/out", false, true, "read+write");
    CHECK(rules.permits("/srv/scenes/a.inc", dsl::FileAccess::read));
    CHECK_FALSE(rules.permits("/srv/scenes/a.inc", dsl::FileAccess::write));
    CHECK(rules.permits("/srv/out/a.txt", dsl::FileAccess::read));  // writing implies reading, as in POV-Ray
    CHECK(rules.permits("/srv/out/a.txt", dsl::FileAccess::write));
    CHECK_FALSE(rules.permits("/etc/passwd", dsl::FileAccess::read));
    rules.level = dsl::IoRestrictions::read_only;
    CHECK(rules.permits("/etc/passwd", dsl::FileAccess::read));
    CHECK_FALSE(rules.permits("/etc/passwd", dsl::FileAccess::write));
    rules.level = dsl::IoRestrictions::none;
    CHECK(rules.permits("/etc/passwd", dsl::FileAccess::write));
}

TEST_CASE("povray.conf is read as POV-Ray 3.7 reads it", "[dsl][file_access]") {
    ::setenv("HOME", "/home/someone", 1);
    dsl::FileAccessRules rules;
    rules.level = dsl::IoRestrictions::none;
    dsl::apply_povray_conf(rules,
                           "; Debian's, in part\n"
                           "[File I/O Security]\n"
                           ";none\n"
                           "restricted  ; the default\n"
                           "[Shellout Security]\n"
                           "forbidden\n"
                           "[Permitted Paths]\n"
                           "read* = %INSTALLDIR%/include\n"
                           "read = \"/srv/with space\"\n"
                           "read+write* = '/tmp/photon out'\n"
                           "  read+write=/srv/out   ; spaces anywhere\n"
                           "read* = %HOME%/scenes\n"
                           "[Custom]\n"
                           "anything = goes\n",
                           "povray.conf");
    CHECK(rules.level == dsl::IoRestrictions::restricted);
    CHECK(rules.level_origin == "povray.conf:4");
    REQUIRE(rules.permitted.size() == 5);
    CHECK(rules.permitted[0].folder == "/usr/share/povray-3.7/include");
    CHECK(rules.permitted[0].descend);
    CHECK_FALSE(rules.permitted[0].writable);
    CHECK(rules.permitted[1].folder == "/srv/with space");
    CHECK_FALSE(rules.permitted[1].descend);
    CHECK(rules.permitted[2].folder == "/tmp/photon out");
    CHECK(rules.permitted[2].descend);
    CHECK(rules.permitted[2].writable);
    CHECK(rules.permitted[3].folder == "/srv/out");
    CHECK(rules.permitted[3].writable);
    CHECK_FALSE(rules.permitted[3].descend);
    CHECK(rules.permitted[3].origin == "povray.conf:11");
    CHECK(rules.permitted[4].folder == "/home/someone/scenes");

    auto error = [](const std::string& text) {
        dsl::FileAccessRules r;
        try {
            dsl::apply_povray_conf(r, text, "bad.conf");
        } catch (const dsl::Error& e) {
            return e.location().str() + ": " + e.message();
        }
        return std::string();
    };
    CHECK(error("[File I/O Security]\n  strict\n") ==
          "bad.conf:2:3: expected `none`, `read-only` or `restricted` in [File I/O Security], found `strict`");
    CHECK(error("[Permitted Paths]\nwrite = /tmp\n") ==
          "bad.conf:2:1: expected `read`, `read*`, `read+write` or `read+write*` = FOLDER, found `write = /tmp`");
    CHECK(error("[Permitted Paths]\nread* /tmp\n") == "bad.conf:2:1: expected `=` and a folder after `read*`");
    CHECK(error("[Permitted Paths]\nread = \"/tmp\n") == "bad.conf:2:1: no closing \" after the folder");
    CHECK(error("read = /tmp\n") ==
          "bad.conf:1:1: expected a section ([File I/O Security], [Shellout Security] or [Permitted Paths]) before `read = /tmp`");
    CHECK(error("[Shellout Security]\nsometimes\n") ==
          "bad.conf:2:1: expected `allowed` or `forbidden` in [Shellout Security], found `sometimes`");
    // Debian's own file, when installed, reads without an error.
    if (std::filesystem::exists("/etc/povray/3.7/povray.conf")) {
        dsl::FileAccessRules debian;
        dsl::apply_povray_conf_file(debian, "/etc/povray/3.7/povray.conf");
        CHECK(debian.level == dsl::IoRestrictions::restricted);
        CHECK(debian.permitted.size() >= 5);
    }
}

TEST_CASE("no construct opens a file outside the permitted folders: absolute, `..` or a link", "[dsl][file_access]") {
    const Layout l;
    const std::string absolute = (l.outside / "secret").string();
    for (const auto& name : {absolute, std::string("../outside/secret"), std::string("link/secret"),
                             std::string("link/../../outside/secret")}) {
        for (const char* ext : {".inc", ".txt", ".png", ".obj", ".ttf"}) {
            for (const auto& [construct, scene] : constructs(name + ext)) {
                INFO(construct << " of " << name << ext);
                const auto [message, full] = l.error(scene);
                CHECK_THAT(message, Contains("reading \"" + name + ext + "\" is not permitted"));
                CHECK_THAT(message, Contains("under the I/O restrictions `restricted` (photon's default)"));
                CHECK(message.rfind("1:", 0) == 0);  // located on the scene's first line
                CHECK(full.find(Layout::secret) == std::string::npos);
                // Nothing of where a link leads.
                if (name.rfind("link/", 0) == 0) CHECK(message.find(l.outside.string()) == std::string::npos);
            }
        }
    }
    // A link to a single file is resolved as well.
    CHECK_THAT(l.error("#include \"linked.inc\"\nsphere { 0, 1 }\n").first,
               Contains("1:10: reading \"linked.inc\" is not permitted"));
    // Not even whether the file is there: a missing file is refused alike.
    CHECK_THAT(l.error("#include \"../outside/missing.inc\"\nsphere { 0, 1 }\n").first,
               Contains("reading \"../outside/missing.inc\" is not permitted"));
}

TEST_CASE("#fopen for writing or appending is refused outside the writable folders", "[dsl][file_access]") {
    const Layout l;
    for (const char* mode : {"write", "append"})
        for (const std::string& name : {(l.outside / "out.txt").string(), std::string("../outside/out.txt"),
                                       std::string("link/out.txt")}) {
            INFO(mode << " " << name);
            CHECK_THAT(l.error("sphere { 0, 1 }\n#fopen F \"" + name + "\" " + mode + "\n").first,
                       Contains("2:10: writing \"" + name + "\" is not permitted"));
        }
    // The scene's folder and its subfolders are writable (photon keeps what is written in memory).
    CHECK(l.error("#fopen F \"data/out.txt\" write\n#write (F, 1)\n#fclose F\nsphere { 0, 1 }\n").first.empty());
    // read-only: reading anywhere, writing still only where permitted.
    dsl::ParseOptions o;
    o.file_access.level = dsl::IoRestrictions::read_only;
    CHECK(l.error("#fopen F \"../outside/secret.txt\" read\nsphere { 0, 1 }\n", o).first.empty());
    CHECK_THAT(l.error("sphere { 0, 1 }\n#fopen F \"../outside/out.txt\" write\n", o).first,
               Contains("writing \"../outside/out.txt\" is not permitted: it is outside the folders a scene may write under "
                        "the I/O restrictions `read-only`"));
}

TEST_CASE("the same constructs read the outside folder once it is permitted", "[dsl][file_access]") {
    const Layout l;
    for (const bool by_link : {false, true}) {
        dsl::ParseOptions o;
        o.file_access.permit(l.outside, false, false, "test");
        const std::string name = by_link ? "link/secret" : (l.outside / "secret").string();
        for (const auto& [construct, scene] : constructs(name + ".inc")) {
            if (construct == "#include" || construct == "#fopen read") continue;  // their text is no scene or data
            INFO(construct << " of " << name);
            CHECK(l.error(scene, o).first.empty());
        }
        // #include and #read find the file (and quote it: a permitted file may be quoted).
        CHECK_THAT(l.error("#include \"" + name + ".inc\"\n", o).first, Contains("SECRET"));
        CHECK_THAT(l.error("#fopen F \"" + name + ".txt\" read\n#read (F, A)\n", o).first,
                   Contains("#read: expected a number, a vector or a string in"));
    }
    dsl::ParseOptions none;
    none.file_access.level = dsl::IoRestrictions::none;
    CHECK_THAT(l.error("#include \"../outside/secret.inc\"\n", none).first, Contains("SECRET"));
}

TEST_CASE("file_exists() says false of a file the scene may not read", "[dsl][file_access]") {
    const Layout l;
    const std::string scene = "#if (file_exists(\"../outside/secret.txt\")) #error \"seen\" #end\n"
                              "#if (!file_exists(\"main.pov\")) #error \"its own file unseen\" #end\nsphere { 0, 1 }\n";
    CHECK(l.error(scene).first.empty());
    dsl::ParseOptions o;
    o.file_access.permit(l.outside, false, false, "test");
    CHECK_THAT(l.error(scene, o).first, Contains("seen"));
}

TEST_CASE("the include path and the scene's subfolders are permitted by default", "[dsl][file_access]") {
    const Layout l;
    l.dir.write("scene/inc/sub.inc", "#declare R = 2;\n");
    l.dir.write("lib/lib.inc", "#declare S = 3;\n");
    dsl::ParseOptions o;
    o.include_paths.push_back(l.dir.path() / "lib");
    CHECK(l.error("#include \"inc/sub.inc\"\n#include \"lib.inc\"\nsphere { 0, R + S }\n", o).first.empty());
    // ... but not the include folder's parent.
    CHECK_THAT(l.error("#include \"lib.inc\"\n#include \"../outside/secret.inc\"\n", o).first,
               Contains("2:10: reading \"../outside/secret.inc\" is not permitted"));
    // The message lists the folders permitted and how to permit more.
    CHECK_THAT(l.error("#include \"../outside/secret.inc\"\n", o).first,
               Contains("the scene's folder " + dsl::resolved_path(l.scene_folder).string()) &&
                   Contains("permit its folder in photon::dsl::ParseOptions::file_access"));
}

TEST_CASE("a scene's data is bounded in bytes and its reading in seconds", "[dsl][errors][limits]") {
    dsl::ParseOptions bytes;
    bytes.max_parse_bytes = 1'000'000;
    CHECK_THAT(error_of("#declare S = \"0123456789\";\n#declare I = 0;\n"
                        "#while (I < 100000) #declare S = concat(S, \"x\"); #declare I = I + 1; #end\nsphere { 0, 1 }\n",
                        bytes),
               Contains("3:34: the scene's data is too large: more than 1000000 bytes"));
    CHECK_THAT(error_of("#declare A = array[100000];\n#declare A[0] = 1;\nsphere { 0, 1 }\n", bytes),
               Contains("2:10: the scene's data is too large"));
    dsl::ParseOptions seconds;
    seconds.max_parse_seconds = 1e-9;  // any read of more than 1024 tokens
    CHECK_THAT(error_of("#declare I = 0;\n#while (I < 1e5) #declare I = I + 1; #end\nsphere { 0, 1 }\n", seconds),
               Contains("the scene takes too long to read: more than 1e-09 seconds"));
    seconds.max_parse_seconds = 0;  // no limit
    CHECK(error_of("#declare I = 0;\n#while (I < 1e3) #declare I = I + 1; #end\nsphere { 0, 1 }\n", seconds).empty());
}

TEST_CASE("the hostile files of issue 48 each end in a located error", "[dsl][errors][limits]") {
    const std::string end = "\nsphere { 0, 1 }\n";
    // Each error is located (line:column) and names the limit it reached.
    CHECK_THAT(error_of("#declare I = 0;\n#while (I < 1e12) #declare I = I + 1; #end" + end),
               Contains("2:1: `#while` loop ran more than 1000000 times"));
    CHECK_THAT(error_of("#macro M() M() #end\nM()" + end), Contains("macro calls nested too deep") || Contains("recursion"));
    CHECK_THAT(error_of("#declare S = \"ab\";\n#while (1) #declare S = concat(S, S); #end" + end),
               Contains("string too long"));
    CHECK_THAT(error_of("#declare A = array[2e9];" + end), Contains("1:20: ") && Contains("array"));
    CHECK_THAT(error_of("#declare F = function(x) { F(x) }" + end), Contains("1:28: "));
    CHECK_THAT(error_of("#include \"/dev/urandom\"" + end), Contains("1:10: reading \"/dev/urandom\" is not permitted"));
    CHECK_THAT(error_of("#include \"/etc/passwd\"" + end), Contains("1:10: reading \"/etc/passwd\" is not permitted"));
    dsl::ParseOptions none;  // no restrictions: /dev/urandom is still no file to read
    none.file_access.level = dsl::IoRestrictions::none;
    CHECK_THAT(error_of("#include \"/dev/urandom\"" + end, none), Contains("1:10: cannot find the include file \"/dev/urandom\""));
}
