// SPDX-License-Identifier: MIT
#pragma once
// The parser's state and the index of its readers. One class, because POV-Ray's language is read
// in one pass where directives, expressions and blocks interleave at any token; its member
// functions are defined by concern in the headers named in each group below.

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

#include "../description.hpp"
#include "../diagnostics.hpp"
#include "../lexer.hpp"
#include "../value.hpp"
#include "keywords.hpp"
#include "parse_options.hpp"

namespace photon::dsl::detail {

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

    // token_stream.hpp
    [[noreturn]] void fail(const SourceLocation& at, std::string message) const;
    [[noreturn]] void fail_expected(const std::string& expected, const Token& found,
                                    const std::string& hint = {}) const;
    void warn(const SourceLocation& at, const std::string& message);
    std::string too_large_message(std::size_t bytes) const;
    static std::filesystem::path weakly_canonical(const std::filesystem::path& p);
    std::shared_ptr<const SourceFile> load(const std::filesystem::path& path, std::string name,
                                           const SourceLocation& from);
    void directive_include(const Token& d);
    void include_from_reader(const Token& s);
    void check_include_loop(const std::filesystem::path& canonical, const Token& s) const;
    Token raw_token();
    static std::string position(const SourceLocation& at);
    std::string position_in(const SourceLocation& at, const SourceLocation& from) const;
    const Token& peek();
    Token next();
    bool accept_symbol(std::string_view s);
    Token expect_symbol(std::string_view s, const std::string& context);
    void optional_comma();
    void open_block(const Token& keyword);
    void close_block(const Token& keyword, const std::string& items, Words known = {});
    void skip_block(const Token& kw);

    // directives.hpp
    void directive(const Token& d);
    bool is_reserved(std::string_view w) const;
    void declare_global(const std::string& name, ValueData v, const SourceLocation& at);
    const Value* lookup(const std::string& name) const;
    void directive_declare(const Token& d, bool local);
    bool parse_condition(const Token& d, bool& guard);
    bool parse_defined_condition(const Token& d, bool negate, bool& guard);
    void start_if(const Token& d, bool cond, bool guard);
    Token skip_branch(const SourceLocation& opened, const std::string& what, bool stop_at_else);
    void loop_again(CondFrame frame);
    bool in_photon_guard() const;
    void directive_default(const Token& d);

    // expressions.hpp
    Numeric parse_expression_for(const std::string& what);
    Numeric parse_expression();
    Numeric parse_or();
    Numeric parse_and();
    Numeric parse_relation();
    Numeric combine(const Numeric& a, const Numeric& b, const Token& op);
    Numeric parse_sum();
    Numeric parse_product();
    Numeric parse_unary();
    Numeric parse_postfix();
    Numeric parse_primary();
    Numeric parse_identifier_value(const Token& t);

    // builtins.hpp
    Numeric parse_function(const Token& f);

    // typed_values.hpp
    double to_float(const Numeric& n, const std::string& what, const SourceLocation& at) const;
    Vector3 to_vector(const Numeric& n, const std::string& what, const SourceLocation& at) const;
    static Color to_color(const Numeric& n);
    double parse_float(const std::string& what, SourceLocation* where = nullptr);
    Vector3 parse_vector(const std::string& what, SourceLocation* where = nullptr);
    std::int64_t parse_integer(const std::string& what, double lo, double hi);
    double parse_nonnegative(const std::string& what);
    bool starts_expression(const Token& t) const;
    bool parse_optional_bool();
    Color parse_color(const std::string& what);

    // transforms.hpp
    bool try_transform(Transform& tr);
    Transform parse_transform_block(const Token& kw);
    Transform parse_transform_body(const Token& kw);

    // materials.hpp
    template <class T>
    bool take_identifier(T& out, const std::string& what, bool numbers_allowed = false);
    Pigment parse_pigment(const Token& kw, Pigment p);
    Pigment parse_pigment_body(const Token& kw, Pigment p);
    Finish parse_finish(const Token& kw, Finish f);
    Reflection parse_reflection(const Token& kw);
    Interior parse_interior(const Token& kw, Interior in);
    Texture parse_texture(const Token& kw, Texture tex);
    Texture parse_texture_body(const Token& kw, Texture tex);

    // objects.hpp
    Texture& ensure_texture(Object& obj);
    void add_primitives(Object& obj, std::size_t n, const SourceLocation& at);
    Object parse_object(const Token& kw);
    void read_obj_mesh(const Token& kw, std::vector<std::array<Vector3, 3>>& tris);
    TriangleShape parse_triangle_corners(const Token& kw);
    void parse_material(const Token& kw, Object& obj);
    void parse_modifiers(const Token& kw, Object& obj);
    ObjectPhotons parse_object_photons(const Token& kw);

    // mesh2.hpp
    MeshShape parse_mesh2(const Token& kw, Object& obj);

    // degradation.hpp
    void degrade(const SourceLocation& at, std::string_view kind, std::string_view keyword,
                 const std::string& message);
    Object parse_skipped_object(const Token& kw);
    bool is_object_keyword(std::string_view w) const;
    void parse_bound_or_clip(const Token& kw);
    void skip_effect(const Token& kw);

    // patterns.hpp
    struct PatternState;
    bool parse_pattern_item(PatternState& st);
    Color parse_list_color(const std::string& what);
    BlendMap parse_blend_map(const Token& kw);
    void parse_blend_entry_body(const Token& kw, BlendMap& map);
    Color pattern_average(const PatternState& st, const Color& fallback, std::string& how);

    // lights_camera.hpp
    Object parse_light(const Token& kw);
    void parse_light_photons(const Token& kw, LightSource& light);
    CameraDescription parse_camera(const Token& kw);

    // settings.hpp
    void parse_global_settings(const Token& kw);
    void parse_estimate(const Token& kw, EstimateDescription& e);
    void parse_pov_photons(const Token& kw);

    // statements.hpp
    SceneDescription parse_main(std::shared_ptr<const SourceFile> file, std::filesystem::path canonical);
    void parse_statements();

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

}  // namespace photon::dsl::detail
