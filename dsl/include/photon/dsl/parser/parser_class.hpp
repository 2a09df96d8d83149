// SPDX-License-Identifier: MIT
#pragma once
// The parser's state and the index of its readers. One class, because POV-Ray's language is read
// in one pass where directives, expressions and blocks interleave at any token; its member
// functions are defined by concern in the headers named in each group below.

#include <algorithm>
#include <chrono>
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
#include "../user_function.hpp"
#include "../value.hpp"
#include "keywords.hpp"
#include "parse_options.hpp"
#include "random_streams.hpp"

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
    /// `#macro NAME (PARAMS) body #end`: where the body is, to be read again at each call.
    struct Macro {
        std::string name;
        std::vector<std::string> params;
        std::vector<bool> optional;  ///< POV-Ray 3.8's `optional` parameters may be left out
        std::shared_ptr<const SourceFile> file;
        std::filesystem::path path;
        Lexer::State body{};
        std::size_t body_end = 0;  ///< where the closing `#end` starts
        SourceLocation at;
    };
    struct FileFrame {
        Lexer lexer;
        std::filesystem::path path;  ///< canonical, for include loops
        /// A macro call reads the macro's body as a frame of its own, up to body_end.
        std::shared_ptr<const Macro> macro;
        SourceLocation called_at;
    };
    enum class CondKind { if_, while_, for_, switch_ };
    struct CondFrame {
        CondFrame(CondKind k, std::size_t depth, SourceLocation opened, Lexer::State start = {}, bool guard = false,
                  std::uint64_t done = 0)
            : kind(k), file_depth(depth), at(std::move(opened)), loop_start(start), photon_guard(guard),
              iterations(done) {}
        CondKind kind;
        std::size_t file_depth;
        SourceLocation at;
        Lexer::State loop_start{};
        bool photon_guard = false;
        std::uint64_t iterations = 0;
        std::string loop_variable;             ///< #for
        double loop_end = 0, loop_step = 1;    ///< #for
        double switch_value = 0;               ///< #switch
        bool case_running = false;             ///< #switch: inside a matching #case, falling through
    };
    /// Raises reading_name_ for a scope: the identifiers read are names (`#declare NAME`,
    /// `#ifdef (NAME)`), so macros are not called and unset array elements are no error.
    struct ReadingName {
        Parser& p;
        explicit ReadingName(Parser& parser) : p(parser) { ++p.reading_name_; }
        ~ReadingName() { --p.reading_name_; }
        ReadingName(const ReadingName&) = delete;
        ReadingName& operator=(const ReadingName&) = delete;
    };
    /// A function body being compiled: its slots by name (parameters, sum/prod variables in
    /// scope) and each node's height, to bound the evaluation's recursion.
    struct FunctionScope {
        UserFunction& f;
        std::vector<std::pair<std::string, std::uint32_t>> names;
        std::vector<std::uint32_t> heights;
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
    void warn(const SourceLocation& at, const std::string& message, Severity severity = Severity::warning);
    std::string too_large_message(std::size_t bytes) const;
    static std::filesystem::path weakly_canonical(const std::filesystem::path& p);
    std::shared_ptr<const SourceFile> load(const std::filesystem::path& path, std::string name,
                                           const SourceLocation& from);
    void directive_include(const Token& d);
    void include_from_reader(const Token& s);
    void push_included_text(const Token& s, std::string text, const std::filesystem::path& key);
    void check_include_loop(const std::filesystem::path& canonical, const Token& s) const;
    void charge_bytes(std::uint64_t bytes, const SourceLocation& at);
    Token raw_token();
    static std::string position(const SourceLocation& at);
    std::string position_in(const SourceLocation& at, const SourceLocation& from) const;
    bool suppressed() const;
    const Token& peek();
    Token next();
    bool accept_symbol(std::string_view s);
    Token expect_symbol(std::string_view s, const std::string& context);
    void optional_comma();
    void open_block(const Token& keyword);
    void close_block(const Token& keyword, const std::string& items, Words known = {});
    void skip_block(const Token& kw);

    // scene_files.hpp
    std::vector<std::filesystem::path> search_places(const std::filesystem::path& written, bool include_path) const;
    std::filesystem::path find_readable(const std::vector<std::filesystem::path>& places, const Token& name);
    void check_writable(const Token& name) const;

    // directives.hpp
    void directive(const Token& d);
    bool is_reserved(std::string_view w) const;
    void directive_declare(const Token& d, bool local);
    std::optional<ValueData> parse_block_value(const Token& t);
    ValueData parse_rvalue(const std::string& what, bool& needs_semicolon, bool sums_only = false);
    void directive_undef();
    bool parse_condition(const Token& d, bool& guard);
    bool parse_defined_condition(const Token& d, bool negate, bool& guard);
    void start_if(const Token& d, bool cond, bool guard);
    Token skip_branch(const SourceLocation& opened, const std::string& what, bool stop_at_else);
    void loop_again(CondFrame frame);
    bool in_photon_guard() const;
    void directive_default(const Token& d);

    // symbol_table.hpp (the storage is scopes_, below)
    void declare_global(const std::string& name, ValueData v, const SourceLocation& at);
    const Value* lookup(const std::string& name) const;
    const Value* lookup_in(std::size_t scope, const std::string& name) const;
    const Value* follow(const Value* v) const;
    void assign(const Token& id, ValueData v, bool local);
    void store_at(std::size_t scope, const std::string& key, ValueData v, const SourceLocation& at);

    // macros.hpp
    void directive_macro(const Token& d);
    bool try_invoke_macro(const Token& t);
    void bind_argument(const Macro& m, std::size_t i, std::unordered_map<std::string, Value>& scope);
    void return_from_macro();
    std::string macro_trace() const;

    // control_flow.hpp
    void directive_switch(const Token& d);
    void directive_case(const Token& d);
    bool case_matches(const Token& d);
    void skip_to_case(const Token& d);
    void directive_break(const Token& d);
    void skip_to_end_of(std::size_t frame);
    void directive_for(const Token& d);
    void for_again(CondFrame frame);

    // arrays.hpp
    Array parse_array(const Token& kw);
    void parse_array_initialiser(Array& a, std::size_t dim, std::size_t& next_index, const Token& kw);
    void set_element(Array& a, std::size_t index, ValueData v, const std::string& name, const SourceLocation& at);
    void expand_array_element(Token& t);
    static bool split_element(const std::string& name, std::string& base, std::vector<std::size_t>& indices);
    static std::size_t flat_index(const Array& a, const std::vector<std::size_t>& indices);
    Numeric parse_array_function(const Token& f);
    [[noreturn]] void fail_unset_element(const Token& t, const Value& array);

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

    // file_io.hpp
    struct OpenFile {
        std::string name, text;
        std::size_t pos = 0;  ///< next character to #read
        bool writing = false;
    };
    void directive_fopen(const Token& d);
    void directive_fclose(const Token& d);
    void directive_write(const Token& d);
    void directive_read(const Token& d);
    OpenFile& open_file(const Token& id, const std::string& directive);
    void close_file(const std::string& id);

    // splines.hpp
    Spline parse_spline(const Token& kw);
    Numeric parse_spline_call(const Token& id, const Spline& s);

    // object_queries.hpp
    Numeric parse_object_query(const Token& f);
    Numeric parse_inside(const Token& f);

    // builtins.hpp
    Numeric parse_function(const Token& f);
    Numeric parse_vector_builtin(const Token& f, const std::vector<Numeric>& args,
                                 const std::vector<SourceLocation>& at);

    // strings.hpp
    bool starts_string(const Token& t) const;
    std::string bounded_string(std::string s, const SourceLocation& at);
    Token parse_string_token(const std::string& what);
    std::string parse_string_expression(const std::string& what);
    bool file_exists_here(const std::string& name) const;
    Numeric parse_string_measure(const Token& f);

    // user_functions.hpp
    std::shared_ptr<const UserFunction> parse_user_function(const Token& kw, const std::string& name);
    std::uint32_t fn_node(FunctionScope& s, FunctionNode n);
    std::uint32_t fn_binary(FunctionScope& s, FunctionNode::Kind kind, const Token& op, std::uint32_t a,
                            std::uint32_t b);
    std::uint32_t fn_expression(FunctionScope& s);
    std::uint32_t fn_or(FunctionScope& s);
    std::uint32_t fn_and(FunctionScope& s);
    std::uint32_t fn_relation(FunctionScope& s);
    std::uint32_t fn_sum(FunctionScope& s);
    std::uint32_t fn_product(FunctionScope& s);
    std::uint32_t fn_unary(FunctionScope& s);
    std::vector<std::uint32_t> fn_arguments(FunctionScope& s, const Token& f);
    std::uint32_t fn_primary(FunctionScope& s);
    static std::string join_names(const std::vector<std::string>& names);
    static int component_index(const std::string& m, int dim);
    std::uint32_t fn_component(const Token& call, const UserFunction& f);
    void check_arity(const UserFunction& f, std::size_t n, const Token& call) const;
    Numeric call_function_value(const Token& t, const UserFunction& f);

    // typed_values.hpp
    double to_float(const Numeric& n, const std::string& what, const SourceLocation& at) const;
    Vector3 to_vector(const Numeric& n, const std::string& what, const SourceLocation& at) const;
    static Color to_color(const Numeric& n);
    Numeric parse_parameter_for(const std::string& what);
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

    // images.hpp
    ImageFile parse_image_file(const Token& kw);
    std::shared_ptr<const ImageMapDesc> parse_image_map_block(const Token& kw);
    void parse_height_field(const Token& kw, Object& obj);
    std::shared_ptr<const ImageMapDesc> parse_bump_map_block(const Token& kw, double& bump_size);

    // objects.hpp
    Texture& ensure_texture(Object& obj);
    void add_primitives(Object& obj, std::size_t n, const SourceLocation& at);
    Object parse_object(const Token& kw);
    MeshFile parse_mesh_file(const Token& kw);
    TriangleShape parse_triangle_corners(const Token& kw);
    void parse_material(const Token& kw, Object& obj);
    void parse_modifiers(const Token& kw, Object& obj);
    ObjectPhotons parse_object_photons(const Token& kw);
    CsgShape parse_csg(const Token& kw, Object& obj);

    // mesh2.hpp
    MeshShape parse_mesh2(const Token& kw, Object& obj);

    // quadrics.hpp
    bool accept_open();
    double finite_value(double v, const std::string& what, const SourceLocation& at);
    double absolute_radius(double r, const std::string& what, const SourceLocation& at);
    void skip_empty_shape(Object& obj, const std::string& keyword, const std::string& why, const SourceLocation& at);
    bool degenerate(Object& obj, const std::string& keyword, const Vector3& base, const Vector3& cap,
                    const SourceLocation& at);
    void parse_cylinder(Object& obj);
    void parse_cone(Object& obj);
    void parse_disc(Object& obj);
    void parse_torus(Object& obj);

    // quadric_polygon.hpp
    void parse_quadric(Object& obj);
    void parse_polygon(Object& obj);
    // prism.hpp
    void parse_prism(Object& obj);
    void parse_text(Object& obj);
    void parse_polynomial(const Token& kw, Object& obj);
    bool parse_polynomial_gate(Object& obj, const std::vector<Object>& bounds);
    // revolved.hpp
    void parse_superellipsoid(Object& obj);
    void parse_lathe(Object& obj);
    void parse_sor(Object& obj);
    // blob.hpp
    void parse_blob(const Token& kw, Object& obj);

    // degradation.hpp
    void degrade(const SourceLocation& at, std::string_view kind, std::string_view keyword,
                 const std::string& message);
    Object parse_skipped_object(const Token& kw);
    bool is_object_keyword(std::string_view w) const;
    void parse_bound_or_clip(const Token& kw, Object& obj);
    bool bound_contains(const Object& obj, const std::vector<Object>& bounds) const;
    void skip_effect(const Token& kw);
    // sky.hpp
    void parse_sky_sphere(const Token& kw);
    SkySphere parse_sky_sphere_block(const Token& kw);

    // fog.hpp
    FogDescription parse_fog_block(const Token& kw);

    // media.hpp
    MediaDescription parse_media_block(const Token& kw);
    Pigment parse_density(const Token& kw);

    // patterns.hpp
    struct PatternState;
    bool parse_pattern_item(PatternState& st);
    Color parse_list_color(const std::string& what, bool* patterned = nullptr);
    BlendMap parse_blend_map(const Token& kw);
    int parse_spiral_arms(const std::string& pattern);
    void parse_blend_entry_body(const Token& kw, BlendMap& map);
    Color pattern_average(const PatternState& st, const Color& fallback, std::string& how);
    std::shared_ptr<const PigmentPattern> evaluated_pattern(const PatternState& st, std::string& why_not) const;
    static bool modifies_pattern(const PatternState& st);
    static void apply_pattern_modifiers(const PatternState& st, PigmentPattern& p);
    Normal parse_normal(const Token& kw, Normal n);

    // lights_camera.hpp
    Object parse_light(const Token& kw);
    void parse_light_photons(const Token& kw, LightSource& light);
    CameraDescription parse_camera(const Token& kw);

    // settings.hpp
    void parse_global_settings(const Token& kw);
    void parse_table_setting(const RenderSetting& s, const Token& kw);
    void parse_settings_block(const Token& kw);
    void parse_pov_photons(const Token& kw);

    // statements.hpp
    SceneDescription parse_main(std::shared_ptr<const SourceFile> file, std::filesystem::path canonical);
    void parse_statements();

    const ParseOptions& options_;
    SceneDescription scene_;
    std::vector<FileFrame> files_;
    std::vector<std::unordered_map<std::string, Value>> scopes_;  ///< the symbol table (symbol_table.hpp)
    std::vector<CondFrame> conds_;
    std::optional<Token> lookahead_;
    std::unordered_map<std::string, std::shared_ptr<const Macro>> macros_;
    unsigned macro_depth_ = 0;
    int reading_name_ = 0;
    std::uint64_t array_elements_ = 0;  ///< array elements made so far, for the bound
    Texture default_texture_;
    std::set<std::string> warned_;
    std::string expecting_;
    double version_ = 3.7;
    std::uint64_t tokens_ = 0;
    std::size_t statements_ = 0;
    unsigned depth_ = 0;
    /// Where directives are not run: the file depth of each condition or value being read.
    /// Only that frame's directives wait; a macro called there runs its body's directives.
    std::vector<std::size_t> suppress_;
    bool in_vector_ = false;  ///< comparisons need parentheses: in a vector or a block's parameter
    bool mentions_photon_version_ = false;
    RandomStreams random_;           ///< seed() and rand()
    std::optional<Token> pending_call_;  ///< a function call whose name parse_block_value read
    std::string declaring_;              ///< the identifier #declare is reading a value for
    std::uint64_t function_steps_ = 0;  ///< user-function evaluation so far, bounded by max_tokens
    std::map<std::string, OpenFile> open_files_;        ///< by file identifier
    std::map<std::string, std::string> written_files_;  ///< by file name: what #write wrote, in memory
    FileAccessRules access_;  ///< the files the scene may open (scene_file_access), set in parse_main
    std::uint64_t parse_bytes_ = 0;  ///< the scene's data made so far, for max_parse_bytes
    std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();  ///< for max_parse_seconds
};

}  // namespace photon::dsl::detail
