// SPDX-License-Identifier: MIT
#pragma once
// Reads a POV-Ray 3.7 scene file (the subset documented in docs/scene-language.md) into a
// SceneDescription, evaluating it as POV-Ray does: directives (#declare, #local, #undef,
// #include, #if/#ifdef/#ifndef/#else/#elseif/#end, #while, #default, #version, #warning,
// #error) are handled in the token stream, so they may appear anywhere; expressions are
// evaluated as they are read. Errors throw dsl::Error with the location; warnings go to
// ParseOptions::diagnostics. Input is bounded (file size, include depth, nesting, loop
// iterations, tokens, primitives), so no file can crash or hang the parser.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include <photon/version.hpp>

#if defined(PHOTON_HAS_OBJ) && PHOTON_HAS_OBJ  // set by the CMake target photon::obj
#include <photon/io/obj_mesh.hpp>
#endif

#include "description.hpp"
#include "diagnostics.hpp"
#include "lexer.hpp"
#include "value.hpp"

namespace photon::dsl {

/// Value of the identifier `photon_version` that photon declares before reading a scene, so that
/// `#ifdef (photon_version)` selects photon's own settings (POV-Ray skips them).
inline constexpr double photon_version = double(PHOTON_VERSION_MAJOR) + double(PHOTON_VERSION_MINOR) / 10.0;

struct ParseOptions {
    /// Searched for `#include` files after the including file's own directory.
    std::vector<std::filesystem::path> include_paths;
    /// When set, `#include "name"` reads the text this returns instead of a file (nullopt: not
    /// found), and the file system is never touched: a sandbox for untrusted scenes (the fuzzer)
    /// and for scenes held in memory. Names are compared as written, for include loops.
    std::function<std::optional<std::string>(const std::string& name)> read_include;
    /// Floats declared before the scene is read (POV-Ray's `Declare=NAME=VALUE`).
    std::map<std::string, double> defines;
    DiagnosticSink diagnostics;
    /// Values of POV-Ray's `image_width` and `image_height`.
    unsigned image_width = 800, image_height = 600;

    std::size_t max_file_bytes = std::size_t(64) << 20;
    unsigned max_include_depth = 32;
    unsigned max_nesting = 128;  ///< blocks, unions and parentheses inside each other
    std::uint64_t max_tokens = 200'000'000;
    std::uint64_t max_loop_iterations = 1'000'000;  ///< per #while loop
    std::size_t max_primitives = 10'000'000;        ///< objects and mesh triangles in the scene
};

namespace detail {

/// Edit distance, for "did you mean" hints.
[[nodiscard]] inline std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

/// A list of words: a keyword table or a braced list written at the call.
struct Words {
    std::span<const std::string_view> list;
    Words() = default;
    Words(std::initializer_list<std::string_view> l) : list(l.begin(), l.size()) {}
    template <std::size_t N>
    Words(const std::string_view (&a)[N]) : list(a) {}
    [[nodiscard]] auto begin() const noexcept { return list.begin(); }
    [[nodiscard]] auto end() const noexcept { return list.end(); }
    [[nodiscard]] std::size_t size() const noexcept { return list.size(); }
};

inline bool one_of(std::string_view w, Words list) { return std::find(list.begin(), list.end(), w) != list.end(); }

/// " (did you mean `x`?)" for the closest candidate within a small distance, or "".
[[nodiscard]] inline std::string suggest(std::string_view word, Words candidates) {
    std::string_view best;
    std::size_t best_d = std::max<std::size_t>(1, std::min<std::size_t>(2, word.size() / 3)) + 1;
    for (std::string_view c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_d) best_d = d, best = c;
    }
    return best.empty() ? std::string() : " (did you mean `" + std::string(best) + "`?)";
}

inline constexpr std::string_view object_keywords[] = {"sphere", "box",   "plane", "triangle", "smooth_triangle",
                                                       "mesh",   "union", "merge", "object",   "light_source"};
inline constexpr std::string_view unsupported_objects[] = {
    "cylinder",      "cone",           "torus",      "disc",         "polygon",    "prism",         "sor",
    "lathe",         "superellipsoid", "blob",       "height_field", "isosurface", "julia_fractal", "parametric",
    "quadric",       "cubic",          "quartic",    "poly",         "polynomial", "sphere_sweep",  "text",
    "bicubic_patch", "mesh2",          "difference", "intersection", "ovus",       "lemon"};
inline constexpr std::string_view statement_keywords[] = {
    "camera",          "light_source", "global_settings", "background", "sphere", "box", "plane", "triangle",
    "smooth_triangle", "mesh",         "union",           "merge",      "object"};
inline constexpr std::string_view color_keywords[] = {"color", "colour", "rgb",  "rgbf",   "rgbt",    "rgbft",
                                                      "red",   "green",  "blue", "filter", "transmit"};
inline constexpr std::string_view constants[] = {"pi", "tau", "x",       "y",     "z",           "t",
                                                 "u",  "v",   "true",    "yes",   "on",          "false",
                                                 "no", "off", "version", "clock", "image_width", "image_height"};
inline constexpr std::string_view functions[] = {
    "abs", "acos",  "asin", "atan", "atan2", "ceil",   "cos",  "cosh",    "defined",    "degrees", "div",
    "exp", "floor", "int",  "ln",   "log",   "max",    "min",  "mod",     "pow",        "radians", "select",
    "sin", "sinh",  "sqrt", "tan",  "tanh",  "vcross", "vdot", "vlength", "vnormalize", "vrotate"};
inline constexpr std::string_view modifier_keywords[] = {
    "texture",      "pigment",           "finish",          "normal",   "interior",
    "material",     "photons",           "translate",       "rotate",   "scale",
    "matrix",       "transform",         "no_shadow",       "no_image", "no_reflection",
    "no_radiosity", "double_illuminate", "inverse",         "hollow",   "sturm",
    "bounded_by",   "clipped_by",        "interior_texture"};
inline constexpr std::string_view finish_keywords[] = {
    "ambient",    "diffuse",         "brilliance", "specular", "roughness", "phong", "phong_size",
    "reflection", "conserve_energy", "emission",   "metallic", "irid",      "crand", "reflection_exponent",
    "subsurface"};
inline constexpr std::string_view light_keywords[] = {"spotlight",
                                                      "point_at",
                                                      "radius",
                                                      "falloff",
                                                      "tightness",
                                                      "area_light",
                                                      "adaptive",
                                                      "jitter",
                                                      "circular",
                                                      "orient",
                                                      "area_illumination",
                                                      "fade_distance",
                                                      "fade_power",
                                                      "shadowless",
                                                      "looks_like",
                                                      "photons",
                                                      "media_interaction",
                                                      "media_attenuation",
                                                      "parallel",
                                                      "cylinder",
                                                      "projected_through",
                                                      "translate",
                                                      "rotate",
                                                      "scale",
                                                      "matrix",
                                                      "transform"};
inline constexpr std::string_view camera_keywords[] = {
    "perspective", "location", "look_at",     "up",           "right",      "direction",
    "sky",         "angle",    "translate",   "rotate",       "scale",      "matrix",
    "transform",   "aperture", "focal_point", "blur_samples", "confidence", "variance"};
inline constexpr std::string_view global_keywords[] = {
    "assumed_gamma",   "ambient_light", "max_trace_level", "adc_bailout",     "radiosity",
    "photons",         "charset",       "number_of_waves", "noise_generator", "max_intersections",
    "irid_wavelength", "hf_gray_16",    "mm_per_unit",     "subsurface"};
/// photon's own global_settings items (POV-Ray does not know them).
inline constexpr std::string_view photon_keywords[] = {"width",
                                                       "height",
                                                       "render_mode",
                                                       "global_photons",
                                                       "caustic_photons",
                                                       "global_estimate",
                                                       "caustic_estimate",
                                                       "max_photon_depth",
                                                       "final_gather",
                                                       "shadow_samples",
                                                       "samples_per_pixel",
                                                       "irradiance_stride",
                                                       "irradiance_cache",
                                                       "sppm_passes",
                                                       "sppm_photons",
                                                       "seed"};
inline constexpr std::string_view other_keywords[] = {"camera",
                                                      "global_settings",
                                                      "background",
                                                      "pigment",
                                                      "finish",
                                                      "interior",
                                                      "texture",
                                                      "ior",
                                                      "target",
                                                      "collect",
                                                      "pass_through",
                                                      "refraction",
                                                      "fresnel",
                                                      "albedo",
                                                      "count",
                                                      "spacing",
                                                      "gather",
                                                      "autostop",
                                                      "expand_thresholds",
                                                      "inside_vector",
                                                      "sky_sphere",
                                                      "fog",
                                                      "rainbow",
                                                      "media",
                                                      "orthographic",
                                                      "fisheye"};

class Parser {
public:
    explicit Parser(const ParseOptions& options) : options_(options) {
        scopes_.emplace_back();
        declare_global("photon_version", Numeric::scalar(photon_version), {});
        for (const auto& [name, value] : options_.defines) declare_global(name, Numeric::scalar(value), {});
        default_texture_.finish = Finish{};
    }

    SceneDescription parse_file(const std::filesystem::path& path) {
        auto file = load(path, path.lexically_normal().string(), {});
        return parse_main(std::move(file), weakly_canonical(path));
    }

    SceneDescription parse_text(std::string text, std::string name) {
        std::filesystem::path path =
            options_.read_include ? std::filesystem::path("<memory>") / name : std::filesystem::current_path() / name;
        auto file = std::make_shared<SourceFile>(SourceFile{std::move(name), std::move(text)});
        if (file->text.size() > options_.max_file_bytes) fail({file, 0, 0}, too_large_message(file->text.size()));
        return parse_main(std::move(file), std::move(path));
    }

private:
    // ---- files, tokens and directives -------------------------------------------------------

    struct FileFrame {
        Lexer lexer;
        std::filesystem::path path;  ///< canonical, for include loops
    };
    enum class CondKind { if_, while_ };
    struct CondFrame {
        CondKind kind;
        std::size_t file_depth;
        SourceLocation at;
        Lexer::State loop_start{};
        bool photon_guard = false;
        std::uint64_t iterations = 0;
    };
    struct Nest {
        Parser& p;
        Nest(Parser& parser, const SourceLocation& at) : p(parser) {
            if (++p.depth_ > p.options_.max_nesting)
                p.fail(at, "nesting too deep: more than " + std::to_string(p.options_.max_nesting) +
                               " blocks, objects, parentheses or directives inside each other");
        }
        ~Nest() { --p.depth_; }
        Nest(const Nest&) = delete;
        Nest& operator=(const Nest&) = delete;
    };

    [[noreturn]] void fail(const SourceLocation& at, std::string message) const { throw Error(at, std::move(message)); }
    [[noreturn]] void fail_expected(const std::string& expected, const Token& found,
                                    const std::string& hint = {}) const {
        fail(found.location, "expected " + expected + ", found " + describe(found) + hint);
    }
    void warn(const SourceLocation& at, const std::string& message) {
        if (!warned_.insert(at.str() + '\x1f' + message).second) return;
        if (options_.diagnostics) options_.diagnostics({Severity::warning, at, message});
    }

    std::string too_large_message(std::size_t bytes) const {
        return "file too large: " + std::to_string(bytes) + " bytes, photon reads scene files of at most " +
               std::to_string(options_.max_file_bytes) + " bytes";
    }

    static std::filesystem::path weakly_canonical(const std::filesystem::path& p) {
        std::error_code ec;
        auto c = std::filesystem::weakly_canonical(p, ec);
        return ec ? std::filesystem::absolute(p) : c;
    }

    std::shared_ptr<const SourceFile> load(const std::filesystem::path& path, std::string name,
                                           const SourceLocation& from) {
        std::error_code ec;
        const SourceLocation where =
            from.known() ? from : SourceLocation{std::make_shared<SourceFile>(SourceFile{name, {}}), 0, 0};
        if (std::filesystem::is_directory(path, ec)) fail(where, "cannot read \"" + name + "\": it is a directory");
        const auto size = std::filesystem::file_size(path, ec);
        if (ec) fail(where, "cannot open \"" + name + "\": " + ec.message());
        if (size > options_.max_file_bytes) fail(where, too_large_message(std::size_t(size)));
        std::ifstream in(path, std::ios::binary);
        if (!in) fail(where, "cannot open \"" + name + "\"");
        std::string text(std::size_t(size), '\0');
        in.read(text.data(), std::streamsize(size));
        if (!in) fail(where, "cannot read \"" + name + "\"");
        return std::make_shared<SourceFile>(SourceFile{std::move(name), std::move(text)});
    }

    SceneDescription parse_main(std::shared_ptr<const SourceFile> file, std::filesystem::path canonical) {
        scene_.at = {file, 1, 1};
        scene_.files.push_back(file);
        files_.push_back({Lexer(file), std::move(canonical)});
        parse_statements();
        return std::move(scene_);
    }

    Token raw_token() {
        for (;;) {
            if (++tokens_ > options_.max_tokens) {
                const Lexer& lexer = files_.back().lexer;
                fail({lexer.file(), lexer.state().line, lexer.state().column},
                     "the scene is too long: more than " + std::to_string(options_.max_tokens) + " tokens read");
            }
            Token t = files_.back().lexer.next();
            if (t.kind != TokenKind::end_of_file) return t;
            if (!conds_.empty() && conds_.back().file_depth == files_.size()) {
                const CondFrame& c = conds_.back();
                fail(t.location, "expected `#end` to close the `" +
                                     std::string(c.kind == CondKind::if_ ? "#if" : "#while") + "` opened at " +
                                     position(c.at) + ", found end of file");
            }
            if (files_.size() == 1) return t;
            files_.pop_back();
            scopes_.pop_back();
        }
    }

    static std::string position(const SourceLocation& at) {
        return std::to_string(at.line) + ":" + std::to_string(at.column);
    }
    std::string position_in(const SourceLocation& at, const SourceLocation& from) const {
        if (at.file == from.file) return position(at);
        return at.str();
    }

    const Token& peek() {
        for (;;) {
            if (lookahead_) {
                if (lookahead_->kind != TokenKind::directive || suppress_ > 0) return *lookahead_;
                Token d = std::move(*lookahead_);
                lookahead_.reset();
                directive(d);
                continue;
            }
            lookahead_ = raw_token();
        }
    }
    Token next() {
        peek();
        Token t = std::move(*lookahead_);
        lookahead_.reset();
        return t;
    }
    bool accept_symbol(std::string_view s) {
        if (!peek().is_symbol(s)) return false;
        next();
        return true;
    }
    Token expect_symbol(std::string_view s, const std::string& context) {
        if (!peek().is_symbol(s)) fail_expected("`" + std::string(s) + "` " + context, peek());
        return next();
    }
    void optional_comma() { accept_symbol(","); }

    /// `{` after a block keyword.
    void open_block(const Token& keyword) {
        if (!peek().is_symbol("{")) fail_expected("`{` after `" + keyword.text + "`", peek());
        next();
    }
    /// `}` closing the block of `keyword`; `items` names what else could come.
    void close_block(const Token& keyword, const std::string& items, Words known = {}) {
        const Token& t = peek();
        if (t.is_symbol("}")) {
            next();
            return;
        }
        const std::string close =
            "`}` to close `" + keyword.text + "` (opened at " + position_in(keyword.location, t.location) + ")";
        if (t.kind == TokenKind::end_of_file) fail_expected(close, t);
        std::string hint;
        if (t.kind == TokenKind::identifier && known.size() > 0) hint = suggest(t.text, known);
        fail_expected(items + " or " + close, t, hint);
    }

    void directive(const Token& d) {
        // A directive's arguments may start another directive (`#undef #undef ...`, a `#while`
        // whose `#end` re-reads the condition); bounded like any nesting, so that no chain of
        // them can overflow the stack.
        const Nest nest(*this, d.location);
        ++statements_;
        const std::string& name = d.text;
        if (name == "declare" || name == "local") {
            directive_declare(d, name == "local");
        } else if (name == "undef") {
            const Token id = next();
            if (id.kind != TokenKind::identifier) fail_expected("an identifier after `#undef`", id);
            for (auto& scope : scopes_) scope.erase(id.text);
        } else if (name == "version") {
            ++suppress_;
            const SourceLocation at = peek().location;
            const double v = to_float(parse_expression_for("the language version"), "the language version", at);
            --suppress_;
            version_ = v;
            scene_.version = v;
            if (v < 3.5) warn(at, "#version " + format_number(v) + ": photon reads scenes with POV-Ray 3.7's rules");
            accept_symbol(";");
        } else if (name == "include") {
            directive_include(d);
        } else if (name == "if" || name == "ifdef" || name == "ifndef") {
            bool guard = false;
            const bool cond =
                name == "if" ? parse_condition(d, guard) : parse_defined_condition(d, name == "ifndef", guard);
            start_if(d, cond, guard);
        } else if (name == "else" || name == "elseif") {
            if (conds_.empty() || conds_.back().file_depth != files_.size() || conds_.back().kind != CondKind::if_)
                fail(d.location, "`#" + name + "` without a matching `#if`");
            skip_branch(conds_.back().at, "#if", false);
            conds_.pop_back();
        } else if (name == "end") {
            if (conds_.empty() || conds_.back().file_depth != files_.size())
                fail(d.location, "`#end` without a matching `#if`, `#ifdef`, `#ifndef` or `#while`");
            CondFrame frame = conds_.back();
            conds_.pop_back();
            if (frame.kind == CondKind::while_) loop_again(frame);
        } else if (name == "while") {
            const Lexer::State start = files_.back().lexer.state();
            bool guard = false;
            if (parse_condition(d, guard)) {
                conds_.push_back({CondKind::while_, files_.size(), d.location, start, guard, 0});
            } else {
                skip_branch(d.location, "#while", false);
            }
        } else if (name == "warning" || name == "debug" || name == "error") {
            const Token s = next();
            if (s.kind != TokenKind::string) fail_expected("a string in double quotes after `#" + name + "`", s);
            if (name == "error") fail(d.location, "#error: " + s.text);
            if (name == "warning") warn(d.location, "#warning: " + s.text);
        } else if (name == "default") {
            directive_default(d);
        } else if (one_of(name, {"macro", "switch", "case", "range", "break", "for", "fopen", "fclose", "read", "write",
                                 "statistics", "render"})) {
            fail(d.location,
                 "`#" + name + "` is not supported by photon's scene language (see docs/scene-language.md)");
        } else {
            fail(d.location,
                 "unknown directive `#" + name + "`" +
                     suggest(name, {"declare", "local", "undef", "include", "if", "ifdef", "ifndef", "else", "elseif",
                                    "end", "while", "version", "warning", "error", "debug", "default"}));
        }
    }

    bool is_reserved(std::string_view w) const {
        return one_of(w, object_keywords) || one_of(w, unsupported_objects) || one_of(w, color_keywords) ||
               one_of(w, constants) || one_of(w, functions) || one_of(w, modifier_keywords) ||
               one_of(w, finish_keywords) || one_of(w, camera_keywords) || one_of(w, global_keywords) ||
               one_of(w, light_keywords) || one_of(w, other_keywords);
    }

    void declare_global(const std::string& name, ValueData v, const SourceLocation& at) {
        scopes_.front()[name] = Value{std::move(v), at};
    }
    const Value* lookup(const std::string& name) const {
        for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
            auto f = it->find(name);
            if (f != it->end()) return &f->second;
        }
        return nullptr;
    }

    void directive_declare(const Token& d, bool local) {
        const Token id = next();
        if (id.kind != TokenKind::identifier) fail_expected("an identifier after `#" + d.text + "`", id);
        if (is_reserved(id.text)) fail(id.location, "cannot #" + d.text + " `" + id.text + "`: it is a keyword");
        expect_symbol("=", "after `#" + d.text + " " + id.text + "`");
        auto store = [&](ValueData v) {
            auto& scope = local ? scopes_.back() : scopes_.front();
            scope[id.text] = Value{std::move(v), id.location};
        };
        const Token t = peek();
        if (t.kind == TokenKind::identifier) {
            const std::string& w = t.text;
            std::optional<ValueData> block;
            if (w == "texture")
                block = parse_texture(next(), default_texture_);
            else if (w == "pigment")
                block = parse_pigment(next(), Pigment{});
            else if (w == "finish")
                block = parse_finish(next(), Finish{});
            else if (w == "interior")
                block = parse_interior(next(), Interior{});
            else if (w == "transform")
                block = parse_transform_block(next());
            else if (w == "camera")
                block = parse_camera(next());
            else if (one_of(w, object_keywords)) {
                block = parse_object(next());
            } else if (one_of(w, unsupported_objects)) {
                unsupported_object(t);
            } else if (const Value* v = lookup(w); v && !std::holds_alternative<Numeric>(v->data)) {
                next();
                block = v->data;
            }
            if (block) {
                store(std::move(*block));
                accept_symbol(";");
                return;
            }
        }
        if (t.kind == TokenKind::string) {
            next();
            store(t.text);
            expect_symbol(";", "after the value of `" + id.text + "`");
            return;
        }
        ++suppress_;
        const Numeric n = parse_expression_for("the value of `" + id.text + "`");
        --suppress_;
        store(n);
        ++suppress_;
        const Token after = peek();
        --suppress_;
        if (!after.is_symbol(";"))
            fail(after.location, "expected `;` after the value of `" + id.text + "`, found " + describe(after));
        next();
    }

    void directive_include(const Token& d) {
        const Token s = next();
        if (s.kind != TokenKind::string) fail_expected("a file name in double quotes after `#include`", s);
        if (files_.size() >= options_.max_include_depth)
            fail(s.location, "includes nested too deep: more than " + std::to_string(options_.max_include_depth) +
                                 " files open at once");
        namespace fs = std::filesystem;
        if (options_.read_include) {
            include_from_reader(s);
            return;
        }
        const fs::path name(s.text);
        std::vector<fs::path> candidates;
        if (name.is_absolute()) {
            candidates.push_back(name);
        } else {
            candidates.push_back(files_.back().path.parent_path() / name);
            for (const auto& dir : options_.include_paths) candidates.push_back(dir / name);
        }
        std::error_code ec;
        fs::path found;
        for (const auto& c : candidates)
            if (fs::is_regular_file(c, ec)) {
                found = c;
                break;
            }
        if (found.empty()) {
            std::string where;
            for (const auto& c : candidates)
                where += (where.empty() ? "" : ", ") + c.parent_path().lexically_normal().string();
            fail(s.location, "cannot find the include file \"" + s.text + "\" (looked in " + where + ")");
        }
        const fs::path canonical = weakly_canonical(found);
        check_include_loop(canonical, s);
        (void)d;
        std::string display = found.lexically_normal().string();
        if (const auto rel = fs::proximate(found, ec); !ec && !rel.empty() && rel.native().rfind("..", 0) != 0)
            display = rel.lexically_normal().string();
        auto file = load(found, display, s.location);
        scene_.files.push_back(file);
        files_.push_back({Lexer(file), canonical});
        scopes_.emplace_back();
    }

    /// `#include` through ParseOptions::read_include: the name alone identifies the file.
    void include_from_reader(const Token& s) {
        const std::filesystem::path key = std::filesystem::path("<memory>") / s.text;
        check_include_loop(key, s);
        std::optional<std::string> text = options_.read_include(s.text);
        if (!text) fail(s.location, "cannot find the include file \"" + s.text + "\"");
        if (text->size() > options_.max_file_bytes) fail(s.location, too_large_message(text->size()));
        auto file = std::make_shared<SourceFile>(SourceFile{s.text, std::move(*text)});
        scene_.files.push_back(file);
        files_.push_back({Lexer(file), key});
        scopes_.emplace_back();
    }

    void check_include_loop(const std::filesystem::path& canonical, const Token& s) const {
        for (std::size_t i = 0; i < files_.size(); ++i)
            if (files_[i].path == canonical) {
                std::string chain;
                for (std::size_t j = i; j < files_.size(); ++j) chain += files_[j].lexer.file()->name + " includes ";
                fail(s.location, "include loop: " + chain + "\"" + s.text + "\" again");
            }
    }

    /// `( expression )` after #if, #elseif or #while. Directives are not run inside it (as in
    /// POV-Ray): `#if #end` is an error here, not an `#end` that re-enters a loop's condition.
    bool parse_condition(const Token& d, bool& guard) {
        ++suppress_;
        expect_symbol("(", "after `#" + d.text + "`");
        const bool saved = mentions_photon_version_;
        mentions_photon_version_ = false;
        const SourceLocation at = peek().location;
        const double v = to_float(parse_expression_for("a condition"), "a condition", at);
        guard = mentions_photon_version_;
        mentions_photon_version_ = saved;
        expect_symbol(")", "to close the condition of `#" + d.text + "`");
        --suppress_;
        return v != 0.0;
    }
    bool parse_defined_condition(const Token& d, bool negate, bool& guard) {
        ++suppress_;
        expect_symbol("(", "after `#" + d.text + "`");
        const Token id = next();
        if (id.kind != TokenKind::identifier) fail_expected("an identifier in `#" + d.text + " ( )`", id);
        expect_symbol(")", "after the identifier of `#" + d.text + "`");
        --suppress_;
        guard = id.text == "photon_version";
        return (lookup(id.text) != nullptr) != negate;
    }

    void start_if(const Token& d, bool cond, bool guard) {
        for (;;) {
            if (cond) {
                conds_.push_back({CondKind::if_, files_.size(), d.location, {}, guard, 0});
                return;
            }
            const Token stop = skip_branch(d.location, "#" + d.text, true);
            if (stop.text == "end") return;
            if (stop.text == "else") {
                cond = true;
                continue;
            }
            bool g = false;
            cond = parse_condition(stop, g);
            guard = guard || g;
        }
    }

    /// Skips the current file's tokens up to the `#end` (or, with `stop_at_else`, an `#else` or
    /// `#elseif`) that belongs to the directive opened at `opened`; returns that directive.
    Token skip_branch(const SourceLocation& opened, const std::string& what, bool stop_at_else) {
        int depth = 0;
        for (;;) {
            if (++tokens_ > options_.max_tokens)
                fail(opened,
                     "the scene is too long: more than " + std::to_string(options_.max_tokens) + " tokens read");
            Token t = files_.back().lexer.next();
            if (t.kind == TokenKind::end_of_file)
                fail(t.location, "expected `#end` to close the `" + what + "` opened at " + position(opened) +
                                     ", found end of file");
            if (t.kind != TokenKind::directive) continue;
            if (one_of(t.text, {"if", "ifdef", "ifndef", "while", "switch", "macro", "for"})) {
                ++depth;
            } else if (t.text == "end") {
                if (depth == 0) return t;
                --depth;
            } else if (depth == 0 && stop_at_else && (t.text == "else" || t.text == "elseif")) {
                return t;
            }
        }
    }

    void loop_again(CondFrame frame) {
        if (++frame.iterations > options_.max_loop_iterations)
            fail(frame.at, "`#while` loop ran more than " + std::to_string(options_.max_loop_iterations) +
                               " times: is its condition ever false?");
        files_.back().lexer.restore(frame.loop_start);
        const Token w{TokenKind::directive, "while", 0, frame.at};
        bool guard = false;
        if (parse_condition(w, guard)) {
            conds_.push_back(frame);
        } else {
            skip_branch(frame.at, "#while", false);
        }
    }

    bool in_photon_guard() const {
        return std::any_of(conds_.begin(), conds_.end(), [](const CondFrame& c) { return c.photon_guard; });
    }

    void directive_default(const Token& d) {
        open_block(d);
        for (;;) {
            const Token t = peek();
            if (t.is_identifier("texture"))
                default_texture_ = parse_texture(next(), default_texture_);
            else if (t.is_identifier("pigment"))
                default_texture_.pigment = parse_pigment(next(), default_texture_.pigment);
            else if (t.is_identifier("finish"))
                default_texture_.finish = parse_finish(next(), default_texture_.finish);
            else
                break;
        }
        close_block(d, "`texture`, `pigment` or `finish`", {"texture", "pigment", "finish"});
    }

    // ---- expressions ------------------------------------------------------------------------

    Numeric parse_expression_for(const std::string& what) {
        const std::string saved = expecting_;
        expecting_ = what;
        Numeric n = parse_expression();
        expecting_ = saved;
        return n;
    }

    Numeric parse_expression() {
        const Nest nest(*this, peek().location);
        Numeric c = parse_or();
        if (peek().is_symbol("?")) {
            const Token q = next();
            const bool cond = to_float(c, "a condition before `?`", q.location) != 0.0;
            Numeric a = parse_expression();
            expect_symbol(":", "in `condition ? a : b`");
            Numeric b = parse_expression();
            return cond ? a : b;
        }
        return c;
    }

    Numeric parse_or() {
        Numeric a = parse_and();
        while (peek().is_symbol("|")) {
            const Token op = next();
            const Numeric b = parse_and();
            a = Numeric::scalar(to_float(a, "a number", op.location) != 0.0 ||
                                to_float(b, "a number", op.location) != 0.0);
        }
        return a;
    }
    Numeric parse_and() {
        Numeric a = parse_relation();
        while (peek().is_symbol("&")) {
            const Token op = next();
            const Numeric b = parse_relation();
            a = Numeric::scalar(to_float(a, "a number", op.location) != 0.0 &&
                                to_float(b, "a number", op.location) != 0.0);
        }
        return a;
    }
    Numeric parse_relation() {
        Numeric a = parse_sum();
        while (!in_vector_) {
            const Token& t = peek();
            if (!(t.kind == TokenKind::symbol && one_of(t.text, {"<", "<=", "=", "!=", ">=", ">"}))) break;
            const Token op = next();
            const Numeric b = parse_sum();
            const double x = to_float(a, "a number to compare", op.location);
            const double y = to_float(b, "a number to compare", op.location);
            bool r = false;
            if (op.text == "<")
                r = x < y;
            else if (op.text == "<=")
                r = x <= y;
            else if (op.text == "=")
                r = x == y;
            else if (op.text == "!=")
                r = x != y;
            else if (op.text == ">=")
                r = x >= y;
            else
                r = x > y;
            a = Numeric::scalar(r);
        }
        return a;
    }

    Numeric combine(const Numeric& a, const Numeric& b, const Token& op) {
        Numeric r;
        r.dim = std::max(a.dim, b.dim);
        r.color = a.color || b.color;
        const int n = r.dim == 0 ? 1 : r.dim;
        for (int i = 0; i < n; ++i) {
            const double x = a.at(i), y = b.at(i);
            double v = 0;
            switch (op.text[0]) {
                case '+':
                    v = x + y;
                    break;
                case '-':
                    v = x - y;
                    break;
                case '*':
                    v = x * y;
                    break;
                default:
                    if (y == 0.0) fail(op.location, "division by zero");
                    v = x / y;
            }
            r.c[std::size_t(i)] = v;
        }
        if (!r.finite()) fail(op.location, "the result of `" + op.text + "` is not a finite number");
        return r;
    }

    Numeric parse_sum() {
        Numeric a = parse_product();
        while (peek().is_symbol("+") || peek().is_symbol("-")) {
            const Token op = next();
            a = combine(a, parse_product(), op);
        }
        return a;
    }
    Numeric parse_product() {
        Numeric a = parse_unary();
        while (peek().is_symbol("*") || peek().is_symbol("/")) {
            const Token op = next();
            a = combine(a, parse_unary(), op);
        }
        return a;
    }
    Numeric parse_unary() {
        const Token& t = peek();
        if (t.is_symbol("-") || t.is_symbol("+") || t.is_symbol("!")) {
            const Token op = next();
            const Nest nest(*this, op.location);
            Numeric v = parse_unary();
            if (op.text == "-")
                for (double& c : v.c) c = -c;
            else if (op.text == "!")
                v = Numeric::scalar(to_float(v, "a number after `!`", op.location) == 0.0);
            return v;
        }
        return parse_postfix();
    }
    Numeric parse_postfix() {
        Numeric v = parse_primary();
        while (peek().is_symbol(".")) {
            const Token dot = next();
            const Token m = next();
            static const std::map<std::string, int, std::less<>> members = {
                {"x", 0},   {"y", 1},     {"z", 2},    {"t", 3},      {"u", 0},       {"v", 1},
                {"red", 0}, {"green", 1}, {"blue", 2}, {"filter", 3}, {"transmit", 4}};
            const auto it = m.kind == TokenKind::identifier ? members.find(m.text) : members.end();
            if (it == members.end())
                fail_expected("a component (x, y, z, t, red, green, blue, filter, transmit) after `.`", m);
            if (v.dim == 0)
                fail(dot.location, "expected a vector or colour before `." + m.text + "`, found " + describe(v));
            if (it->second >= v.dim)
                fail(m.location,
                     "`." + m.text + "` is beyond the " + std::to_string(v.dim) + " components of " + describe(v));
            v = Numeric::scalar(v.c[std::size_t(it->second)]);
        }
        return v;
    }

    Numeric parse_primary() {
        const Token t = peek();
        if (t.kind == TokenKind::number) {
            next();
            return Numeric::scalar(t.number);
        }
        if (t.is_symbol("(")) {
            next();
            const bool saved = in_vector_;
            in_vector_ = false;
            Numeric v = parse_expression();
            in_vector_ = saved;
            expect_symbol(")", "to close the `(` at " + position(t.location));
            return v;
        }
        if (t.is_symbol("<")) {
            next();
            Numeric v;
            const bool saved = in_vector_;
            for (;;) {
                in_vector_ = true;
                const SourceLocation at = peek().location;
                const Numeric c = parse_expression();
                in_vector_ = saved;
                if (!c.is_float()) fail(at, "expected a number as a component of the vector, found " + describe(c));
                if (v.dim == 5) fail(at, "a vector has at most 5 components");
                v.c[std::size_t(v.dim++)] = c.c[0];
                if (accept_symbol(",")) continue;
                if (peek().is_symbol(">")) break;
                fail_expected("`,` or `>` in the vector opened at " + position(t.location), peek());
            }
            next();
            if (v.dim < 2) fail(t.location, "a vector needs at least 2 components, found 1");
            return v;
        }
        if (t.kind == TokenKind::identifier) return parse_identifier_value(t);
        fail_expected(expecting_.empty() ? std::string("a number or vector") : expecting_, t);
    }

    Numeric parse_identifier_value(const Token& t) {
        const std::string& w = t.text;
        if (one_of(w, color_keywords)) return Numeric::from_color(parse_color(expecting_));
        if (one_of(w, constants)) {
            next();
            if (w == "pi") return Numeric::scalar(3.14159265358979323846);
            if (w == "tau") return Numeric::scalar(2 * 3.14159265358979323846);
            if (w == "x") return Numeric::vector({1, 0, 0});
            if (w == "y") return Numeric::vector({0, 1, 0});
            if (w == "z") return Numeric::vector({0, 0, 1});
            if (w == "t") {
                Numeric n;
                n.c = {0, 0, 0, 1, 0};
                n.dim = 4;
                return n;
            }
            if (w == "u" || w == "v") {
                Numeric n;
                n.c = {w == "u" ? 1.0 : 0.0, w == "v" ? 1.0 : 0.0, 0, 0, 0};
                n.dim = 2;
                return n;
            }
            if (w == "true" || w == "yes" || w == "on") return Numeric::scalar(1);
            if (w == "false" || w == "no" || w == "off") return Numeric::scalar(0);
            if (w == "version") return Numeric::scalar(version_);
            if (w == "clock") return Numeric::scalar(0);
            if (w == "image_width") return Numeric::scalar(options_.image_width);
            return Numeric::scalar(options_.image_height);
        }
        if (one_of(w, functions)) return parse_function(next());
        if (const Value* v = lookup(w)) {
            if (w == "photon_version") mentions_photon_version_ = true;
            if (const auto* n = std::get_if<Numeric>(&v->data)) {
                next();
                return *n;
            }
            fail(t.location, "expected " + (expecting_.empty() ? std::string("a number or vector") : expecting_) +
                                 ", found `" + w + "` (" + type_name(v->data) + ", declared at " +
                                 position_in(v->at, t.location) + ")");
        }
        if (is_reserved(w) || one_of(w, photon_keywords) || one_of(w, light_keywords))
            fail_expected(expecting_.empty() ? std::string("a number or vector") : expecting_, t);
        std::string best;
        std::size_t best_d = 3;
        for (const auto& scope : scopes_)
            for (const auto& [name, value] : scope) {
                const std::size_t d = edit_distance(w, name);
                if (d < best_d && d <= std::max<std::size_t>(1, w.size() / 3)) best_d = d, best = name;
            }
        fail(t.location, "undefined identifier `" + w + "`" + (best.empty() ? "" : " (did you mean `" + best + "`?)"));
    }

    Numeric parse_function(const Token& f) {
        const std::string& w = f.text;
        expect_symbol("(", "after `" + w + "`");
        const bool saved = in_vector_;
        in_vector_ = false;
        if (w == "defined") {
            const Token id = next();
            if (id.kind != TokenKind::identifier) fail_expected("an identifier in `defined( )`", id);
            if (id.text == "photon_version") mentions_photon_version_ = true;
            expect_symbol(")", "to close `defined(`");
            in_vector_ = saved;
            return Numeric::scalar(lookup(id.text) != nullptr);
        }
        std::vector<Numeric> args;
        std::vector<SourceLocation> at;
        if (!peek().is_symbol(")")) {
            for (;;) {
                at.push_back(peek().location);
                args.push_back(parse_expression_for("an argument of `" + w + "`"));
                if (!accept_symbol(",")) break;
            }
        }
        expect_symbol(")", "to close the arguments of `" + w + "`");
        in_vector_ = saved;
        auto arity = [&](std::size_t lo, std::size_t hi) {
            if (args.size() < lo || args.size() > hi)
                fail(f.location,
                     "`" + w + "` takes " +
                         (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
                         " argument" + (hi == 1 ? "" : "s") + ", found " + std::to_string(args.size()));
        };
        auto num = [&](std::size_t i) {
            return to_float(args[i], "a number as argument " + std::to_string(i + 1) + " of `" + w + "`", at[i]);
        };
        auto vec = [&](std::size_t i) {
            return to_vector(args[i], "a vector as argument " + std::to_string(i + 1) + " of `" + w + "`", at[i]);
        };
        Numeric r;
        constexpr double deg = 3.14159265358979323846 / 180.0;
        if (one_of(w, {"abs", "acos", "asin", "atan", "ceil", "cos", "cosh", "degrees", "exp", "floor", "int", "ln",
                       "log", "radians", "sin", "sinh", "sqrt", "tan", "tanh"})) {
            arity(1, 1);
            const double a = num(0);
            double v = 0;
            if (w == "abs")
                v = std::abs(a);
            else if (w == "acos")
                v = std::acos(a);
            else if (w == "asin")
                v = std::asin(a);
            else if (w == "atan")
                v = std::atan(a);
            else if (w == "ceil")
                v = std::ceil(a);
            else if (w == "cos")
                v = std::cos(a);
            else if (w == "cosh")
                v = std::cosh(a);
            else if (w == "degrees")
                v = a / deg;
            else if (w == "exp")
                v = std::exp(a);
            else if (w == "floor")
                v = std::floor(a);
            else if (w == "int")
                v = std::trunc(a);
            else if (w == "ln")
                v = std::log(a);
            else if (w == "log")
                v = std::log10(a);
            else if (w == "radians")
                v = a * deg;
            else if (w == "sin")
                v = std::sin(a);
            else if (w == "sinh")
                v = std::sinh(a);
            else if (w == "sqrt")
                v = std::sqrt(a);
            else if (w == "tan")
                v = std::tan(a);
            else
                v = std::tanh(a);
            r = Numeric::scalar(v);
        } else if (one_of(w, {"atan2", "div", "mod", "pow"})) {
            arity(2, 2);
            const double a = num(0), b = num(1);
            if ((w == "div" || w == "mod") && b == 0.0) fail(at[1], "division by zero in `" + w + "`");
            r = Numeric::scalar(w == "atan2" ? std::atan2(a, b)
                                : w == "div" ? std::trunc(a / b)
                                : w == "mod" ? std::fmod(a, b)
                                             : std::pow(a, b));
        } else if (w == "min" || w == "max") {
            arity(1, 1000);
            double v = num(0);
            for (std::size_t i = 1; i < args.size(); ++i) v = w == "min" ? std::min(v, num(i)) : std::max(v, num(i));
            r = Numeric::scalar(v);
        } else if (w == "select") {
            arity(3, 4);
            const double s = num(0);
            if (args.size() == 3)
                r = s < 0 ? args[1] : args[2];
            else
                r = s < 0 ? args[1] : (s == 0 ? args[2] : args[3]);
        } else if (w == "vlength") {
            arity(1, 1);
            r = Numeric::scalar(glm::length(vec(0)));
        } else if (w == "vnormalize") {
            arity(1, 1);
            const Vector3 a = vec(0);
            if (glm::length(a) == 0.0) fail(at[0], "`vnormalize` of a zero vector");
            r = Numeric::vector(glm::normalize(a));
        } else if (w == "vdot") {
            arity(2, 2);
            r = Numeric::scalar(glm::dot(vec(0), vec(1)));
        } else if (w == "vcross") {
            arity(2, 2);
            r = Numeric::vector(glm::cross(vec(0), vec(1)));
        } else {  // vrotate
            arity(2, 2);
            r = Numeric::vector(Transform::rotate(vec(1)).vector(vec(0)));
        }
        if (!r.finite()) fail(f.location, "the result of `" + w + "` is not a finite number");
        return r;
    }

    double to_float(const Numeric& n, const std::string& what, const SourceLocation& at) const {
        if (!n.is_float()) fail(at, "expected " + what + " (a number), found " + describe(n));
        return n.c[0];
    }
    Vector3 to_vector(const Numeric& n, const std::string& what, const SourceLocation& at) const {
        if (n.dim == 0) return Vector3(n.c[0]);
        if (n.dim == 2 || n.dim == 3) return {n.c[0], n.c[1], n.c[2]};
        fail(at, "expected " + what + " (a vector), found " + describe(n));
    }
    /// POV-Ray's promotion: a float sets all five components; a 3-vector is rgb.
    static Color to_color(const Numeric& n) {
        if (n.dim == 0) return {Vector3(n.c[0]), n.c[0], n.c[0]};
        return {{n.at(0), n.at(1), n.at(2)}, n.at(3), n.at(4)};
    }

    double parse_float(const std::string& what, SourceLocation* where = nullptr) {
        const SourceLocation at = peek().location;
        if (where) *where = at;
        return to_float(parse_expression_for(what), what, at);
    }
    Vector3 parse_vector(const std::string& what, SourceLocation* where = nullptr) {
        const SourceLocation at = peek().location;
        if (where) *where = at;
        return to_vector(parse_expression_for(what), what, at);
    }
    /// A whole number in [lo, hi] (fractions are truncated, as POV-Ray does).
    std::int64_t parse_integer(const std::string& what, double lo, double hi) {
        SourceLocation at;
        const double v = parse_float(what, &at);
        // Whole numbers in full (1000000, not 1e+06), so the bound reads as it would be written.
        auto whole = [](double x) {
            return x == std::floor(x) && std::abs(x) < 1e15 ? std::to_string(std::int64_t(x)) : format_number(x);
        };
        if (!(v >= lo && v <= hi))
            fail(at, what + " must be a whole number from " + whole(lo) + " to " + whole(hi) + ", found " + whole(v));
        return std::int64_t(v);
    }
    double parse_nonnegative(const std::string& what) {
        SourceLocation at;
        const double v = parse_float(what, &at);
        if (v < 0) fail(at, what + " must be >= 0, found " + format_number(v));
        return v;
    }

    bool starts_expression(const Token& t) const {
        if (t.kind == TokenKind::number) return true;
        if (t.kind == TokenKind::symbol) return one_of(t.text, {"(", "<", "-", "+", "!"});
        if (t.kind != TokenKind::identifier) return false;
        if (one_of(t.text, constants) || one_of(t.text, functions) || one_of(t.text, color_keywords)) return true;
        const Value* v = lookup(t.text);
        return v && std::holds_alternative<Numeric>(v->data);
    }
    /// `on`, `off`, any number, or nothing (meaning on).
    bool parse_optional_bool() {
        if (!starts_expression(peek())) return true;
        return parse_float("`on` or `off`") != 0.0;
    }

    /// COLOR: [color|colour] followed by rgb/rgbf/rgbt/rgbft VECTOR, red/green/blue/filter/transmit
    /// FLOAT, or a colour expression, in any combination.
    Color parse_color(const std::string& what) {
        Color c;
        bool any = false;
        const Token first = peek();
        if (first.is_identifier("color") || first.is_identifier("colour")) next();
        for (;;) {
            const Token t = peek();
            if (t.kind == TokenKind::identifier && one_of(t.text, {"rgb", "rgbf", "rgbt", "rgbft"})) {
                next();
                const SourceLocation at = peek().location;
                const Numeric n = parse_expression_for("the value of `" + t.text + "`");
                const int need = t.text == "rgb" ? 3 : (t.text == "rgbft" ? 5 : 4);
                if (n.dim != 0 && n.dim < need)
                    fail(at, "expected " + std::to_string(need) + " components after `" + t.text + "`, found " +
                                 describe(n));
                c.rgb = {n.at(0), n.at(1), n.at(2)};
                if (t.text == "rgbf") c.filter = n.at(3);
                if (t.text == "rgbt") c.transmit = n.at(3);
                if (t.text == "rgbft") c.filter = n.at(3), c.transmit = n.at(4);
            } else if (t.kind == TokenKind::identifier &&
                       one_of(t.text, {"red", "green", "blue", "filter", "transmit"})) {
                next();
                const double v = parse_float("the value of `" + t.text + "`");
                if (t.text == "red")
                    c.rgb.x = v;
                else if (t.text == "green")
                    c.rgb.y = v;
                else if (t.text == "blue")
                    c.rgb.z = v;
                else if (t.text == "filter")
                    c.filter = v;
                else
                    c.transmit = v;
            } else if (!any && starts_expression(t) && !t.is_identifier("color") && !t.is_identifier("colour")) {
                c = to_color(parse_expression_for(what.empty() ? "a colour" : what));
            } else {
                break;
            }
            any = true;
        }
        if (!any) fail_expected(what.empty() ? std::string("a colour") : what + " (a colour)", peek());
        return c;
    }

    // ---- transformations --------------------------------------------------------------------

    bool try_transform(Transform& tr) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) return false;
        if (t.text == "translate") {
            next();
            tr = tr.then(Transform::translate(parse_vector("the translation after `translate`")));
        } else if (t.text == "rotate") {
            next();
            tr = tr.then(Transform::rotate(parse_vector("the angles in degrees after `rotate`")));
        } else if (t.text == "scale") {
            next();
            SourceLocation at;
            const Vector3 s = parse_vector("the scale factors after `scale`", &at);
            if (s.x == 0 || s.y == 0 || s.z == 0)
                fail(at, "scale by zero would flatten the object: expected non-zero scale factors, found <" +
                             format_number(s.x) + ", " + format_number(s.y) + ", " + format_number(s.z) + ">");
            tr = tr.then(Transform::scale(s));
        } else if (t.text == "matrix") {
            next();
            const Token open = expect_symbol("<", "after `matrix`");
            std::array<double, 12> m{};
            const bool saved = in_vector_;
            for (std::size_t i = 0; i < 12; ++i) {
                in_vector_ = true;
                m[i] = parse_float("entry " + std::to_string(i + 1) + " of the 12 numbers of `matrix`");
                in_vector_ = saved;
                if (i < 11) expect_symbol(",", "between the 12 numbers of `matrix`");
            }
            expect_symbol(">", "after the 12 numbers of `matrix`");
            const Transform mt = Transform::matrix(m);
            if (std::abs(glm::determinant(mt.linear)) < 1e-300)
                fail(open.location, "the matrix is singular (its 3x3 part has determinant 0)");
            tr = tr.then(mt);
        } else if (t.text == "transform") {
            next();
            if (peek().is_symbol("{")) {
                tr = tr.then(parse_transform_body(t));
            } else {
                const Token id = next();
                const Value* v = id.kind == TokenKind::identifier ? lookup(id.text) : nullptr;
                if (!v || !std::holds_alternative<Transform>(v->data))
                    fail_expected("a transform identifier or `{` after `transform`", id);
                tr = tr.then(std::get<Transform>(v->data));
            }
        } else {
            return false;
        }
        return true;
    }

    Transform parse_transform_block(const Token& kw) {
        if (!peek().is_symbol("{")) fail_expected("`{` after `transform`", peek());
        return parse_transform_body(kw);
    }
    Transform parse_transform_body(const Token& kw) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        Transform tr;
        if (peek().kind == TokenKind::identifier) {
            const Value* v = lookup(peek().text);
            if (v && std::holds_alternative<Transform>(v->data)) {
                next();
                tr = std::get<Transform>(v->data);
            }
        }
        for (;;) {
            if (try_transform(tr)) continue;
            if (peek().is_identifier("inverse")) {
                next();
                tr = tr.inverse();
                continue;
            }
            break;
        }
        close_block(kw, "`translate`, `rotate`, `scale`, `matrix`, `transform` or `inverse`",
                    {"translate", "rotate", "scale", "matrix", "transform", "inverse"});
        return tr;
    }

    // ---- textures ---------------------------------------------------------------------------

    /// A declared `T` at the start of a block (`texture { T_Ident ...`), copied into `out`. Any
    /// other declared type is an error naming `what` was expected, except numbers and colours
    /// where `numbers_allowed`.
    template <class T>
    bool take_identifier(T& out, const std::string& what, bool numbers_allowed = false) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) return false;
        const Value* v = lookup(t.text);
        if (!v) return false;
        if (const T* typed = std::get_if<T>(&v->data)) {
            next();
            out = *typed;
            return true;
        }
        if (numbers_allowed && std::holds_alternative<Numeric>(v->data)) return false;
        fail(t.location, "expected " + what + ", found `" + t.text + "` (" + type_name(v->data) + ", declared at " +
                             position_in(v->at, t.location) + ")");
    }

    Pigment parse_pigment(const Token& kw, Pigment p) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        p.at = kw.location;
        take_identifier(p, "a colour or a pigment identifier", true);
        Transform ignored;
        for (;;) {
            const Token t = peek();
            if (t.is_symbol("}")) break;
            if (try_transform(ignored)) continue;
            if (t.is_identifier("quick_color") || t.is_identifier("quick_colour")) {
                next();
                parse_color("the quick colour");
                continue;
            }
            if (t.kind == TokenKind::identifier &&
                one_of(t.text,
                       {"color_map", "colour_map", "pigment_map", "image_map", "checker",    "hexagon",  "brick",
                        "gradient",  "bozo",       "granite",     "marble",    "wood",       "agate",    "spotted",
                        "leopard",   "onion",      "radial",      "ripples",   "waves",      "wrinkles", "bumps",
                        "dents",     "crackle",    "average",     "object",    "uv_mapping", "function", "pattern"}))
                fail(t.location, "photon supports only solid colours in `pigment`, found `" + t.text + "`");
            if (starts_expression(t) || t.is_identifier("color") || t.is_identifier("colour")) {
                p.color = parse_color("the colour of the pigment");
                continue;
            }
            if (t.kind == TokenKind::identifier) {
                if (const Value* v = lookup(t.text))
                    fail(t.location, "expected a colour or pigment in `pigment`, found `" + t.text + "` (" +
                                         type_name(v->data) + ")");
            }
            break;
        }
        close_block(kw, "a colour", {"color", "rgb", "rgbf", "rgbt", "rgbft"});
        return p;
    }

    Finish parse_finish(const Token& kw, Finish f) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        f.at = kw.location;
        take_identifier(f, "a finish identifier or a finish item");
        for (;;) {
            const Token t = peek();
            if (t.kind != TokenKind::identifier || !one_of(t.text, finish_keywords)) break;
            next();
            const std::string& w = t.text;
            f.written[w] = t.location;
            if (w == "ambient") {
                f.ambient = to_color(parse_expression_for("the ambient colour")).rgb;
            } else if (w == "diffuse") {
                if (peek().is_identifier("albedo")) next();
                f.diffuse = parse_nonnegative("`diffuse`");
                if (accept_symbol(",")) {
                    f.diffuse_back = parse_nonnegative("the back-side `diffuse`");
                    f.written["diffuse_back"] = t.location;
                }
            } else if (w == "brilliance") {
                f.brilliance = parse_float("`brilliance`");
            } else if (w == "specular") {
                if (peek().is_identifier("albedo")) next();
                f.specular = parse_float("`specular`");
            } else if (w == "roughness") {
                f.roughness = parse_float("`roughness`");
            } else if (w == "phong") {
                if (peek().is_identifier("albedo")) next();
                f.phong = parse_nonnegative("`phong`");
            } else if (w == "phong_size") {
                SourceLocation at;
                f.phong_size = parse_float("`phong_size`", &at);
                if (!(f.phong_size > 0))
                    fail(at, "`phong_size` must be positive, found " + format_number(f.phong_size));
            } else if (w == "metallic") {
                f.metallic = starts_expression(peek()) ? parse_float("`metallic`") : 1.0;
            } else if (w == "reflection") {
                f.reflection = parse_reflection(t);
            } else if (w == "reflection_exponent") {
                if (!f.reflection) f.reflection = Reflection{};
                f.reflection->exponent = parse_float("`reflection_exponent`");
            } else if (w == "conserve_energy") {
                f.conserve_energy = parse_optional_bool();
            } else if (w == "emission") {
                f.emission = to_color(parse_expression_for("the emission colour")).rgb;
            } else if (w == "irid") {
                skip_block(t);
            } else if (w == "crand") {
                parse_float("`crand`");
            } else {
                fail(t.location, "`subsurface` is not supported by photon");
            }
        }
        close_block(kw,
                    "a finish item (ambient, diffuse, brilliance, specular, phong, phong_size, reflection, "
                    "conserve_energy, emission)",
                    finish_keywords);
        return f;
    }

    Reflection parse_reflection(const Token& kw) {
        Reflection r;
        r.at = kw.location;
        auto reflectance = [&](const char* what) {
            SourceLocation at;
            at = peek().location;
            const Vector3 v = to_color(parse_expression_for(what)).rgb;
            if (v.x < 0 || v.y < 0 || v.z < 0)
                fail(at, std::string(what) + " must be >= 0, found " + describe(Numeric::vector(v)));
            return v;
        };
        if (!peek().is_symbol("{")) {
            r.max = r.min = reflectance("the reflection colour");
            return r;
        }
        const Nest nest(*this, kw.location);
        open_block(kw);
        r.max = r.min = reflectance("the reflection");
        if (accept_symbol(",") || starts_expression(peek())) {
            r.max = reflectance("the maximum reflection");
            r.variable = true;
        }
        for (;;) {
            const Token t = peek();
            if (t.is_identifier("fresnel")) {
                next();
                r.fresnel = parse_optional_bool();
            } else if (t.is_identifier("falloff")) {
                next();
                r.falloff = parse_float("`falloff`");
            } else if (t.is_identifier("exponent")) {
                next();
                r.exponent = parse_float("`exponent`");
            } else if (t.is_identifier("metallic")) {
                next();
                r.metallic = starts_expression(peek()) ? parse_float("`metallic`") : 1.0;
            } else {
                break;
            }
        }
        close_block(kw, "`fresnel`, `falloff`, `exponent` or `metallic`",
                    {"fresnel", "falloff", "exponent", "metallic"});
        return r;
    }

    Interior parse_interior(const Token& kw, Interior in) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        in.at = kw.location;
        take_identifier(in, "an interior identifier or `ior`");
        for (;;) {
            const Token t = peek();
            if (t.is_identifier("ior")) {
                next();
                SourceLocation at;
                in.ior = parse_float("the index of refraction after `ior`", &at);
                if (!(in.ior > 0)) fail(at, "ior must be positive, found " + format_number(in.ior));
                in.written["ior"] = t.location;
            } else if (t.kind == TokenKind::identifier &&
                       one_of(t.text,
                              {"caustics", "dispersion", "dispersion_samples", "fade_distance", "fade_power"})) {
                next();
                const double v = parse_float("`" + t.text + "`");
                if (v != 0 && !(t.text == "dispersion" && v == 1) && t.text != "dispersion_samples")
                    warn(t.location, "interior `" + t.text + "` is ignored: photon's glass is clear, with one ior");
            } else if (t.is_identifier("fade_color") || t.is_identifier("fade_colour")) {
                next();
                parse_color("the fade colour");
                warn(t.location, "interior `" + t.text + "` is ignored: photon's glass does not absorb");
            } else if (t.is_identifier("media")) {
                fail(t.location, "`media` is not supported by photon");
            } else {
                break;
            }
        }
        close_block(kw, "`ior`", {"ior", "caustics", "dispersion", "fade_distance", "fade_power", "fade_color"});
        return in;
    }

    Texture parse_texture(const Token& kw, Texture tex) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        tex.at = kw.location;
        if (!take_identifier(tex, "a texture identifier, `pigment` or `finish`")) {
            if (peek().kind == TokenKind::identifier &&
                one_of(peek().text, {"material_map", "tiles", "checker", "gradient", "texture_map", "image_pattern"}))
                fail(peek().location,
                     "photon supports only plain textures (one pigment and one finish), found `" + peek().text + "`");
        }
        tex.at = kw.location;
        Transform ignored;
        for (;;) {
            const Token t = peek();
            if (t.is_identifier("pigment"))
                tex.pigment = parse_pigment(next(), tex.pigment);
            else if (t.is_identifier("finish"))
                tex.finish = parse_finish(next(), tex.finish);
            else if (t.is_identifier("normal")) {
                next();
                skip_block(t);
                warn(t.location, "`normal` is ignored: photon does not perturb normals");
            } else if (try_transform(ignored)) {
                continue;
            } else {
                break;
            }
        }
        close_block(kw, "`pigment`, `finish` or `normal`", {"pigment", "finish", "normal"});
        return tex;
    }

    /// Skips a `{ ... }` block after `kw`, nested blocks included.
    void skip_block(const Token& kw) {
        open_block(kw);
        int depth = 1;
        while (depth > 0) {
            const Token t = next();
            if (t.kind == TokenKind::end_of_file)
                fail_expected("`}` to close `" + kw.text + "` (opened at " + position_in(kw.location, t.location) + ")",
                              t);
            if (t.is_symbol("{")) ++depth;
            if (t.is_symbol("}")) --depth;
        }
    }

    // ---- objects ----------------------------------------------------------------------------

    [[noreturn]] void unsupported_object(const Token& t) {
        if (t.text == "difference" || t.text == "intersection")
            fail(t.location, "photon does not support the CSG operation `" + t.text + "`: only `union` and `merge`");
        fail(t.location, "photon does not support the object `" + t.text +
                             "`: use sphere, box, plane, triangle, mesh, union or object");
    }

    Texture& ensure_texture(Object& obj) {
        if (!obj.texture) obj.texture = default_texture_;
        return *obj.texture;
    }

    void add_primitives(Object& obj, std::size_t n, const SourceLocation& at) {
        obj.primitives += n;
        if (obj.primitives > options_.max_primitives)
            fail(at, "the scene is too large: more than " + std::to_string(options_.max_primitives) +
                         " objects and triangles");
    }

    Object parse_object(const Token& kw) {
        const Nest nest(*this, kw.location);
        const std::string& w = kw.text;
        if (w == "light_source") return parse_light(kw);
        Object obj;
        obj.at = kw.location;
        open_block(kw);
        if (w == "sphere") {
            SphereShape s;
            s.center = parse_vector("the centre of the sphere");
            optional_comma();
            SourceLocation at;
            s.radius = parse_float("the radius of the sphere", &at);
            if (!(s.radius > 0)) fail(at, "sphere radius must be positive, found " + format_number(s.radius));
            obj.shape = s;
        } else if (w == "box") {
            BoxShape b;
            b.corner1 = parse_vector("the first corner of the box");
            optional_comma();
            b.corner2 = parse_vector("the second corner of the box");
            obj.shape = b;
        } else if (w == "plane") {
            PlaneShape p;
            SourceLocation at;
            p.normal = parse_vector("the normal of the plane", &at);
            if (glm::length(p.normal) == 0.0) fail(at, "the normal of the plane must not be zero");
            optional_comma();
            p.distance = parse_float("the distance of the plane from the origin");
            obj.shape = p;
        } else if (w == "triangle" || w == "smooth_triangle") {
            obj.shape = parse_triangle_corners(kw);
        } else if (w == "mesh") {
            auto tris = std::make_shared<std::vector<std::array<Vector3, 3>>>();
            if (peek().is_identifier("obj")) read_obj_mesh(next(), *tris);
            while (peek().is_identifier("triangle") || peek().is_identifier("smooth_triangle")) {
                const Token tk = next();
                const Nest inner(*this, tk.location);
                open_block(tk);
                tris->push_back(parse_triangle_corners(tk).vertices);
                if (peek().is_identifier("texture"))
                    fail(peek().location,
                         "per-triangle textures in a `mesh` are not supported: give the mesh one texture");
                close_block(tk, "the triangle's corners");
                if (tris->size() > options_.max_primitives)
                    fail(tk.location, "the scene is too large: more than " + std::to_string(options_.max_primitives) +
                                          " objects and triangles");
            }
            if (tris->empty()) fail_expected("`triangle` or `obj \"file.obj\"` in `mesh`", peek());
            obj.primitives = tris->size();
            obj.shape = MeshShape{std::move(tris)};
        } else if (w == "union" || w == "merge") {
            UnionShape u;
            u.merge = w == "merge";
            if (u.merge) warn(kw.location, "`merge` is read as `union`: photon keeps the inner surfaces");
            obj.primitives = 0;
            for (;;) {
                const Token& t = peek();
                if (t.kind != TokenKind::identifier) break;
                if (one_of(t.text, unsupported_objects)) unsupported_object(t);
                if (!one_of(t.text, object_keywords)) break;
                const Token ck = next();
                u.children.push_back(std::make_shared<const Object>(parse_object(ck)));
                add_primitives(obj, u.children.back()->primitives, ck.location);
            }
            if (u.children.empty()) fail_expected("an object in `" + w + "`", peek());
            obj.shape = std::move(u);
        } else {  // object
            const Token t = peek();
            if (t.kind == TokenKind::identifier && one_of(t.text, object_keywords) && t.text != "object") {
                obj = parse_object(next());
            } else if (t.kind == TokenKind::identifier && one_of(t.text, unsupported_objects)) {
                unsupported_object(t);
            } else {
                const Value* v = t.kind == TokenKind::identifier ? lookup(t.text) : nullptr;
                if (!v) {
                    if (t.kind == TokenKind::identifier && !is_reserved(t.text))
                        fail(t.location, "undefined identifier `" + t.text + "`");
                    fail_expected("an object identifier in `object`", t);
                }
                if (!std::holds_alternative<Object>(v->data))
                    fail(t.location, "expected an object identifier in `object`, found `" + t.text + "` (" +
                                         type_name(v->data) + ")");
                next();
                obj = std::get<Object>(v->data);
            }
            if (std::holds_alternative<LightSource>(obj.shape)) {
                while (try_transform(obj.transform)) {
                }
                close_block(kw, "a transformation", {"translate", "rotate", "scale", "matrix", "transform"});
                return obj;
            }
        }
        parse_modifiers(kw, obj);
        close_block(kw,
                    "an object modifier (texture, pigment, finish, interior, photons, translate, rotate, scale, "
                    "matrix, no_shadow)",
                    modifier_keywords);
        return obj;
    }

    /// `obj "file.obj"` in a mesh: the file's triangles, its path relative to the scene file
    /// that names it. Needs photon::obj (tinyobjloader); errors point at the file name.
    void read_obj_mesh(const Token& kw, std::vector<std::array<Vector3, 3>>& tris) {
        const Token s = next();
        if (s.kind != TokenKind::string) fail_expected("a file name in double quotes after `obj`", s);
#if defined(PHOTON_HAS_OBJ) && PHOTON_HAS_OBJ
        namespace fs = std::filesystem;
        const fs::path name(s.text);
        const fs::path path = name.is_absolute() ? name : files_.back().path.parent_path() / name;
        std::error_code ec;
        std::string display = path.lexically_normal().string();
        if (const auto rel = fs::proximate(path, ec); !ec && !rel.empty() && rel.native().rfind("..", 0) != 0)
            display = rel.lexically_normal().string();
        if (!fs::is_regular_file(path, ec))
            fail(s.location, "cannot find the mesh file \"" + s.text + "\" (looked for " + display + ")");
        ObjTriangles<double> obj;
        try {
            obj = photon::detail::parse_obj_file<double>(path, display);
        } catch (const ObjError& e) {
            fail(s.location, std::string("cannot read the mesh: ") + e.what());
        }
        for (const std::string& w : obj.warnings) warn(s.location, display + ": " + w);
        if (obj.triangles.empty()) fail(s.location, "the mesh file " + display + " has no faces");
        if (obj.triangles.size() > options_.max_primitives)
            fail(s.location, "the scene is too large: more than " + std::to_string(options_.max_primitives) +
                                 " objects and triangles");
        tris.reserve(obj.triangles.size());
        for (const auto& t : obj.triangles)
            tris.push_back({obj.positions[t[0]], obj.positions[t[1]], obj.positions[t[2]]});
        (void)kw;
#else
        (void)tris;
        fail(kw.location, "this program was built without OBJ support: `mesh { obj \"" + s.text +
                              "\" }` needs photon::obj (tinyobjloader)");
#endif
    }

    TriangleShape parse_triangle_corners(const Token& kw) {
        TriangleShape t;
        const bool smooth = kw.text == "smooth_triangle";
        for (int i = 0; i < 3; ++i) {
            if (i > 0) optional_comma();
            t.vertices[std::size_t(i)] = parse_vector("corner " + std::to_string(i + 1) + " of the triangle");
            if (smooth) {
                optional_comma();
                parse_vector("the normal at corner " + std::to_string(i + 1));
            }
        }
        if (smooth) warn(kw.location, "`smooth_triangle` normals are ignored: photon shades triangles flat");
        return t;
    }

    void parse_material(const Token& kw, Object& obj) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        for (;;) {
            const Token t = peek();
            if (t.is_identifier("texture"))
                obj.texture = parse_texture(next(), default_texture_);
            else if (t.is_identifier("interior"))
                obj.interior = parse_interior(next(), obj.interior.value_or(Interior{}));
            else
                break;
        }
        close_block(kw, "`texture` or `interior`", {"texture", "interior"});
    }

    void parse_modifiers(const Token& kw, Object& obj) {
        bool had_texture = false;
        for (;;) {
            const Token t = peek();
            if (t.kind != TokenKind::identifier) return;
            if (try_transform(obj.transform)) continue;
            const std::string& w = t.text;
            if (w == "texture") {
                if (had_texture)
                    fail(t.location, "layered textures are not supported: expected one `texture` per object");
                had_texture = true;
                obj.texture = parse_texture(next(), default_texture_);
            } else if (w == "pigment") {
                Texture& tex = ensure_texture(obj);
                tex.pigment = parse_pigment(next(), tex.pigment);
                tex.at = t.location;
            } else if (w == "finish") {
                Texture& tex = ensure_texture(obj);
                tex.finish = parse_finish(next(), tex.finish);
                if (!tex.at.known()) tex.at = t.location;
            } else if (w == "normal") {
                next();
                skip_block(t);
                warn(t.location, "`normal` is ignored: photon does not perturb normals");
            } else if (w == "interior") {
                obj.interior = parse_interior(next(), obj.interior.value_or(Interior{}));
            } else if (w == "material") {
                parse_material(next(), obj);
            } else if (w == "photons") {
                obj.photons = parse_object_photons(next());
            } else if (w == "no_shadow") {
                next();
                obj.no_shadow = true;
            } else if (one_of(w, {"no_image", "no_reflection", "no_radiosity", "double_illuminate", "inverse"})) {
                next();
                obj.ignored[w] = t.location;
                warn(t.location, "`" + w + "` is ignored by photon");
            } else if (one_of(w, {"hollow", "sturm"})) {
                next();
                parse_optional_bool();
            } else if (w == "inside_vector" && std::holds_alternative<MeshShape>(obj.shape)) {
                next();
                parse_vector("the inside vector of the mesh");
            } else if (w == "interior_texture") {
                next();
                parse_texture(t, default_texture_);
                warn(t.location, "`interior_texture` is ignored: photon uses one texture for both sides");
            } else if (w == "bounded_by" || w == "clipped_by") {
                fail(t.location, "`" + w + "` is not supported by photon");
            } else if (one_of(w, object_keywords) && std::holds_alternative<UnionShape>(obj.shape)) {
                fail(t.location,
                     "objects in `" + kw.text + "` must come before its modifiers: found `" + w + "` after a modifier");
            } else {
                return;
            }
        }
    }

    ObjectPhotons parse_object_photons(const Token& kw) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        ObjectPhotons p;
        p.at = kw.location;
        for (;;) {
            const Token t = peek();
            if (t.is_identifier("target")) {
                next();
                p.target = true;
                if (starts_expression(peek())) p.spacing_multiplier = parse_float("the spacing multiplier of `target`");
            } else if (t.is_identifier("reflection")) {
                next();
                p.reflection = parse_optional_bool();
            } else if (t.is_identifier("refraction")) {
                next();
                p.refraction = parse_optional_bool();
            } else if (t.is_identifier("collect")) {
                next();
                p.collect = parse_optional_bool();
            } else if (t.is_identifier("pass_through")) {
                next();
                p.pass_through = parse_optional_bool();
            } else if (t.is_identifier("split_union")) {
                next();
                parse_optional_bool();
            } else {
                break;
            }
        }
        close_block(kw, "`target`, `reflection`, `refraction`, `collect` or `pass_through`",
                    {"target", "reflection", "refraction", "collect", "pass_through", "split_union"});
        return p;
    }

    Object parse_light(const Token& kw) {
        open_block(kw);
        Object obj;
        obj.at = kw.location;
        LightSource light;
        light.at = kw.location;
        bool from_identifier = false;
        if (peek().kind == TokenKind::identifier) {
            if (const Value* v = lookup(peek().text)) {
                if (const auto* o = std::get_if<Object>(&v->data); o && std::holds_alternative<LightSource>(o->shape)) {
                    next();
                    obj = *o;
                    light = std::get<LightSource>(o->shape);
                    from_identifier = true;
                }
            }
        }
        if (!from_identifier) {
            light.position = parse_vector("the position of the light");
            optional_comma();
            light.written["color"] = peek().location;
            light.color = parse_color("the colour of the light");
        }
        Spotlight spot = light.spotlight.value_or(Spotlight{});
        bool is_spot = light.spotlight.has_value();
        AreaLight area = light.area.value_or(AreaLight{});
        for (;;) {
            const Token t = peek();
            if (t.kind != TokenKind::identifier) break;
            if (try_transform(obj.transform)) continue;
            const std::string& w = t.text;
            if (!one_of(w, light_keywords)) break;
            next();
            light.written[w] = t.location;
            if (w == "spotlight") {
                is_spot = true;
                spot.at = t.location;
            } else if (w == "point_at") {
                spot.point_at = parse_vector("the point after `point_at`");
            } else if (w == "radius" || w == "falloff") {
                SourceLocation at;
                const double a = parse_float("the angle in degrees after `" + w + "`", &at);
                if (!(a >= 0 && a <= 180))
                    fail(at, "`" + w + "` must be an angle from 0 to 180 degrees, found " + format_number(a));
                (w == "radius" ? spot.radius : spot.falloff) = a;
            } else if (w == "tightness") {
                spot.tightness = parse_nonnegative("`tightness`");
            } else if (w == "area_light") {
                area.at = t.location;
                area.axis1 = parse_vector("the first axis of the area light");
                optional_comma();
                area.axis2 = parse_vector("the second axis of the area light");
                optional_comma();
                area.size1 = int(parse_integer("the number of lights along the first axis", 1, 1024));
                optional_comma();
                area.size2 = int(parse_integer("the number of lights along the second axis", 1, 1024));
                light.area = area;
            } else if (w == "adaptive") {
                area.adaptive = int(parse_integer("`adaptive`", 0, 16));
            } else if (w == "jitter") {
                area.jitter = parse_optional_bool();
            } else if (w == "circular") {
                area.circular = parse_optional_bool();
            } else if (w == "orient") {
                area.orient = parse_optional_bool();
            } else if (w == "area_illumination") {
                parse_optional_bool();
            } else if (w == "fade_distance") {
                SourceLocation at;
                light.fade_distance = parse_float("the distance after `fade_distance`", &at);
                if (!(light.fade_distance >= 0))
                    fail(at, "`fade_distance` must be >= 0, found " + format_number(light.fade_distance));
            } else if (w == "fade_power") {
                SourceLocation at;
                light.fade_power = parse_float("the exponent after `fade_power`", &at);
                if (!(light.fade_power >= 0))
                    fail(at, "`fade_power` must be >= 0, found " + format_number(light.fade_power));
            } else if (w == "shadowless") {
                light.shadowless = true;
            } else if (w == "looks_like") {
                const Nest nest(*this, t.location);
                open_block(t);
                const Token ok = next();
                if (ok.kind != TokenKind::identifier || !one_of(ok.text, object_keywords))
                    fail_expected("an object in `looks_like`", ok);
                Object shape = parse_object(ok);
                parse_modifiers(t, shape);
                close_block(t, "object modifiers");
                light.looks_like = true;
            } else if (w == "media_interaction" || w == "media_attenuation") {
                parse_optional_bool();
            } else if (w == "photons") {
                parse_light_photons(t, light);
            } else if (w == "parallel" || w == "cylinder" || w == "projected_through") {
                fail(t.location,
                     "photon does not support `" + w + "` lights: use a point light, an area light or a spotlight");
            }
        }
        if (is_spot) light.spotlight = spot;
        if (light.area) {
            light.area->adaptive = area.adaptive, light.area->jitter = area.jitter;
            light.area->circular = area.circular, light.area->orient = area.orient;
        } else if (light.written.count("circular") || light.written.count("orient") ||
                   light.written.count("adaptive") || light.written.count("jitter")) {
            warn(kw.location, "`circular`, `orient`, `adaptive` and `jitter` have no effect without `area_light`");
        }
        if (!is_spot)
            for (const char* k : {"point_at", "radius", "falloff", "tightness"})
                if (light.written.count(k))
                    warn(light.written[k], std::string("`") + k + "` has no effect without `spotlight`");
        obj.shape = light;
        close_block(kw,
                    "a light_source item (spotlight, area_light, fade_distance, fade_power, photons, translate, ...)",
                    light_keywords);
        return obj;
    }

    void parse_light_photons(const Token& kw, LightSource& light) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        for (;;) {
            const Token t = peek();
            if (t.is_identifier("reflection")) {
                next();
                light.photon_reflection = parse_optional_bool();
            } else if (t.is_identifier("refraction")) {
                next();
                light.photon_refraction = parse_optional_bool();
            } else if (t.is_identifier("area_light")) {
                next();
                light.photon_area_light = parse_optional_bool();
            } else {
                break;
            }
        }
        close_block(kw, "`reflection`, `refraction` or `area_light`", {"reflection", "refraction", "area_light"});
    }

    CameraDescription parse_camera(const Token& kw) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        CameraDescription cam;
        take_identifier(cam, "a camera identifier or a camera item");
        cam.at = kw.location;
        for (;;) {
            const Token t = peek();
            if (t.kind != TokenKind::identifier) break;
            if (try_transform(cam.transform)) continue;
            const std::string& w = t.text;
            if (one_of(w, {"orthographic", "fisheye", "ultra_wide_angle", "omnimax", "panoramic", "spherical",
                           "cylinder", "mesh_camera"}))
                fail(t.location, "photon supports only the `perspective` camera, found `" + w + "`");
            if (!one_of(w, camera_keywords)) break;
            next();
            cam.written[w] = t.location;
            if (w == "perspective") continue;
            if (w == "location")
                cam.location = parse_vector("the camera location");
            else if (w == "look_at")
                cam.look_at = parse_vector("the point after `look_at`");
            else if (w == "up")
                cam.up = parse_vector("the vector after `up`");
            else if (w == "right")
                cam.right = parse_vector("the vector after `right`");
            else if (w == "direction")
                cam.direction = parse_vector("the vector after `direction`");
            else if (w == "sky")
                cam.sky = parse_vector("the vector after `sky`");
            else if (w == "angle") {
                SourceLocation at;
                const double a = parse_float("the horizontal field of view in degrees after `angle`", &at);
                if (!(a > 0 && a < 180))
                    fail(at, "camera `angle` must be between 0 and 180 degrees, found " + format_number(a));
                cam.angle = a;
            } else if (w == "focal_point") {
                parse_vector("the focal point");
                warn(t.location, "`focal_point` is ignored: photon's camera is a pinhole");
            } else {
                parse_float("`" + w + "`");
                if (w == "aperture")
                    warn(t.location, "`aperture` is ignored: photon's camera is a pinhole (no depth of field)");
            }
        }
        close_block(kw, "a camera item (location, look_at, up, right, direction, sky, angle, translate, rotate)",
                    camera_keywords);
        return cam;
    }

    // ---- global settings --------------------------------------------------------------------

    void parse_global_settings(const Token& kw) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        GlobalSettings& g = scene_.settings;
        if (!g.at.known()) g.at = kw.location;
        PhotonSettings& p = g.photon;
        for (;;) {
            const Token t = peek();
            if (t.kind != TokenKind::identifier) break;
            const std::string& w = t.text;
            const bool photon_own = one_of(w, photon_keywords);
            if (!photon_own && !one_of(w, global_keywords)) break;
            next();
            g.written[w] = t.location;
            if (photon_own && !in_photon_guard())
                warn(t.location, "`" + w +
                                     "` is photon's own setting and POV-Ray stops at it: write it inside "
                                     "`#ifdef (photon_version) ... #end`");
            auto count = [&](const std::string& what) { return std::uint64_t(parse_integer(what, 0, 1e12)); };
            // The library's bounds (photon::SettingsLimits), so that they are reported where written.
            auto positive = [&](const std::string& what, double hi) { return unsigned(parse_integer(what, 1, hi)); };
            if (w == "assumed_gamma") {
                SourceLocation at;
                g.assumed_gamma = parse_float("`assumed_gamma`", &at);
                if (*g.assumed_gamma != 1.0)
                    warn(at, "assumed_gamma " + format_number(*g.assumed_gamma) +
                                 ": photon reads every colour as linear (as with assumed_gamma 1.0)");
            } else if (w == "ambient_light") {
                g.ambient_light = to_color(parse_expression_for("the ambient light colour")).rgb;
            } else if (w == "max_trace_level") {
                g.max_trace_level = unsigned(parse_integer("`max_trace_level`", 1, 256));
            } else if (w == "adc_bailout") {
                g.adc_bailout = parse_nonnegative("`adc_bailout`");
            } else if (w == "radiosity") {
                skip_block(t);
                g.radiosity = true;
            } else if (w == "photons") {
                parse_pov_photons(t);
            } else if (w == "subsurface") {
                fail(t.location, "`subsurface` is not supported by photon");
            } else if (w == "charset" || w == "noise_generator" || w == "number_of_waves" || w == "max_intersections" ||
                       w == "irid_wavelength" || w == "hf_gray_16" || w == "mm_per_unit") {
                if (w == "irid_wavelength")
                    parse_color("the wavelengths");
                else if (w == "charset")
                    next();
                else if (w == "hf_gray_16")
                    parse_optional_bool();
                else
                    parse_float("`" + w + "`");
            } else if (w == "width") {
                p.width = unsigned(parse_integer("`width`", 1, 65536));
            } else if (w == "height") {
                p.height = unsigned(parse_integer("`height`", 1, 65536));
            } else if (w == "render_mode") {
                const Token m = next();
                const std::string mode =
                    m.kind == TokenKind::string ? m.text : (m.kind == TokenKind::identifier ? m.text : "");
                if (mode != "rt" && mode != "pm" && mode != "pm_direct" && mode != "pm-direct" && mode != "sppm")
                    fail_expected("`rt`, `pm`, `pm_direct` or `sppm` after `render_mode`", m);
                p.render_mode = mode == "pm-direct" ? "pm_direct" : mode;
            } else if (w == "global_photons") {
                p.global_photons = count("`global_photons`");
            } else if (w == "caustic_photons") {
                p.caustic_photons = count("`caustic_photons`");
            } else if (w == "global_estimate" || w == "caustic_estimate") {
                parse_estimate(t, w == "global_estimate" ? p.global_estimate : p.caustic_estimate);
            } else if (w == "max_photon_depth") {
                p.max_photon_depth = positive("`max_photon_depth`", 1e4);
            } else if (w == "final_gather") {
                p.final_gather = unsigned(parse_integer("`final_gather`", 0, 1e6));
            } else if (w == "shadow_samples") {
                p.shadow_samples = positive("`shadow_samples`", 1e6);
            } else if (w == "samples_per_pixel") {
                p.samples_per_pixel = positive("`samples_per_pixel`", 1e6);
            } else if (w == "irradiance_stride") {
                p.irradiance_stride = unsigned(parse_integer("`irradiance_stride`", 0, 1e6));
            } else if (w == "irradiance_cache") {
                SourceLocation at;
                const double a = parse_float("`irradiance_cache`", &at);
                if (!(a >= 0 && a <= 1)) fail(at, "`irradiance_cache` error must be from 0 (off) to 1, found " + format_number(a));
                p.irradiance_cache = a;
            } else if (w == "sppm_passes") {
                p.sppm_passes = positive("`sppm_passes`", 1e6);
            } else if (w == "sppm_photons") {
                p.sppm_photons = std::uint64_t(parse_integer("`sppm_photons`", 1, 2147483648.0));
            } else {  // seed
                p.seed = count("`seed`");
            }
        }
        close_block(
            kw,
            "a global setting (assumed_gamma, ambient_light, max_trace_level, adc_bailout, radiosity, photons"
            ", or photon's own: global_photons, caustic_photons, global_estimate, ...)",
            {"assumed_gamma", "ambient_light", "max_trace_level", "adc_bailout", "radiosity", "photons", "width",
             "height", "render_mode", "global_photons", "caustic_photons", "global_estimate", "caustic_estimate",
             "max_photon_depth", "final_gather", "shadow_samples", "samples_per_pixel", "irradiance_stride",
             "irradiance_cache", "sppm_passes", "sppm_photons", "seed"});
    }

    void parse_estimate(const Token& kw, EstimateDescription& e) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        for (;;) {
            const Token t = peek();
            if (t.is_identifier("count")) {
                next();
                e.count = unsigned(parse_integer("the photons per estimate after `count`", 1, 1e6));
            } else if (t.is_identifier("radius")) {
                next();
                SourceLocation at;
                e.radius = parse_float("the maximum radius after `radius`", &at);
                if (!(*e.radius > 0))
                    fail(at, "the estimate radius must be positive, found " + format_number(*e.radius));
            } else if (t.is_identifier("flatten")) {
                next();
                SourceLocation at;
                e.flatten = parse_float("`flatten`", &at);
                if (!(*e.flatten >= 1)) fail(at, "`flatten` must be >= 1, found " + format_number(*e.flatten));
            } else if (t.is_identifier("probes")) {
                next();
                e.probes = unsigned(parse_integer("`probes`", 0, 1024));
            } else {
                break;
            }
        }
        close_block(kw, "`count`, `radius`, `flatten` or `probes`", {"count", "radius", "flatten", "probes"});
    }

    void parse_pov_photons(const Token& kw) {
        const Nest nest(*this, kw.location);
        open_block(kw);
        PovPhotons ph = scene_.settings.photons.value_or(PovPhotons{});
        ph.at = kw.location;
        for (;;) {
            const Token t = peek();
            if (t.kind != TokenKind::identifier) break;
            const std::string& w = t.text;
            if (w == "count") {
                next();
                ph.count = std::uint64_t(parse_integer("the photon count", 0, 1e12));
            } else if (w == "spacing") {
                next();
                ph.spacing = parse_nonnegative("`spacing`");
            } else if (w == "gather") {
                next();
                ph.gather_min = unsigned(parse_integer("the minimum of `gather`", 0, 1e6));
                optional_comma();
                ph.gather_max = unsigned(parse_integer("the maximum of `gather`", 1, 1e6));
            } else if (w == "max_trace_level") {
                next();
                ph.max_trace_level = unsigned(parse_integer("`max_trace_level`", 1, 256));
            } else if (w == "radius") {
                next();
                double values[4] = {0, 0, 0, 0};
                int n = 0;
                while (n < 4 && starts_expression(peek())) {
                    values[n++] = parse_float("the values of `radius`");
                    if (!accept_symbol(",")) break;
                }
                if (n > 0 && values[0] > 0) ph.radius = values[0];
            } else if (one_of(w, {"jitter", "autostop", "adc_bailout"})) {
                next();
                parse_float("`" + w + "`");
                ph.ignored[w] = t.location;
            } else if (w == "expand_thresholds") {
                next();
                parse_float("`expand_thresholds`");
                optional_comma();
                parse_float("`expand_thresholds`");
                ph.ignored[w] = t.location;
            } else if (w == "media") {
                next();
                parse_float("`media`");
                while (accept_symbol(",")) parse_float("`media`");
                ph.ignored[w] = t.location;
            } else if (w == "save_file" || w == "load_file") {
                next();
                const Token s = next();
                if (s.kind != TokenKind::string) fail_expected("a file name in double quotes", s);
                warn(t.location, "`" + w + "` is ignored: photon always traces its photons");
            } else {
                break;
            }
        }
        close_block(
            kw, "a photons setting (spacing, count, gather, max_trace_level, radius, autostop, jitter)",
            {"spacing", "count", "gather", "max_trace_level", "radius", "autostop", "jitter", "expand_thresholds"});
        scene_.settings.photons = ph;
    }

    // ---- statements -------------------------------------------------------------------------

    void parse_statements() {
        std::size_t primitives = 0;
        for (;;) {
            const Token t = peek();
            if (t.kind == TokenKind::end_of_file) {
                if (scene_.objects.empty() && !scene_.camera) {
                    if (statements_ == 0)
                        fail({t.location.file, 1, 1},
                             "empty scene file: expected a camera, a light_source or an object, found end of file");
                    fail(t.location, "nothing to render: expected a light_source or an object, found end of file");
                }
                return;
            }
            ++statements_;
            if (t.kind == TokenKind::identifier) {
                const std::string& w = t.text;
                if (w == "camera") {
                    if (scene_.camera)
                        warn(t.location,
                             "this camera replaces the one at " + position_in(scene_.camera->at, t.location));
                    scene_.camera = parse_camera(next());
                    continue;
                }
                if (w == "global_settings") {
                    parse_global_settings(next());
                    continue;
                }
                if (w == "background") {
                    const Token kw = next();
                    open_block(kw);
                    const Color c = parse_color("the background colour");
                    close_block(kw, "nothing more");
                    if (c.rgb != Vector3(0.0))
                        warn(kw.location, "the background colour is ignored: photon's background is black");
                    continue;
                }
                if (one_of(w, {"sky_sphere", "fog", "rainbow", "media", "photons", "radiosity"}))
                    fail(t.location,
                         "`" + w + "` is not supported by photon" +
                             std::string(w == "photons" || w == "radiosity" ? " here: it belongs in `global_settings`"
                                                                            : ""));
                if (one_of(w, unsupported_objects)) unsupported_object(t);
                if (one_of(w, object_keywords)) {
                    Object obj = parse_object(next());
                    if (!std::holds_alternative<LightSource>(obj.shape)) obj.default_texture = default_texture_;
                    primitives += obj.primitives;
                    if (primitives > options_.max_primitives)
                        fail(t.location, "the scene is too large: more than " +
                                             std::to_string(options_.max_primitives) + " objects and triangles");
                    scene_.objects.push_back(std::move(obj));
                    continue;
                }
                if (const Value* v = lookup(w)) {
                    std::string hint = " (" + type_name(v->data) + ")";
                    if (std::holds_alternative<Object>(v->data))
                        hint = " (" + type_name(v->data) + ": write `object { " + w + " }`)";
                    fail_expected("a statement (camera, light_source, an object, global_settings or a #directive)", t,
                                  hint);
                }
                fail_expected("a statement (camera, light_source, an object, global_settings or a #directive)", t,
                              suggest(w, statement_keywords));
            }
            fail_expected("a statement (camera, light_source, an object, global_settings or a #directive)", t);
        }
    }

    const ParseOptions& options_;
    SceneDescription scene_;
    std::vector<FileFrame> files_;
    std::vector<std::unordered_map<std::string, Value>> scopes_;
    std::vector<CondFrame> conds_;
    std::optional<Token> lookahead_;
    Texture default_texture_;
    std::set<std::string> warned_;
    std::string expecting_;
    double version_ = 3.7;
    std::uint64_t tokens_ = 0;
    std::size_t statements_ = 0;
    unsigned depth_ = 0;
    int suppress_ = 0;
    bool in_vector_ = false;
    bool mentions_photon_version_ = false;
};

}  // namespace detail

/// Reads the scene file at `path`. Throws dsl::Error on bad input.
[[nodiscard]] inline SceneDescription parse_file(const std::filesystem::path& path, const ParseOptions& options = {}) {
    detail::Parser parser(options);
    return parser.parse_file(path);
}

/// Reads a scene from `text`; `name` is the file name in messages, and includes are looked up
/// relative to the current directory.
[[nodiscard]] inline SceneDescription parse_string(std::string text, std::string name = "<string>",
                                                   const ParseOptions& options = {}) {
    detail::Parser parser(options);
    return parser.parse_text(std::move(text), std::move(name));
}

}  // namespace photon::dsl
