// SPDX-License-Identifier: MIT
#pragma once
// Top-level statements of a scene file, and the start of reading.

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// Reads the main file `file` (known as `canonical` for include loops and file access) to its end.
inline SceneDescription Parser::parse_main(std::shared_ptr<const SourceFile> file, std::filesystem::path canonical) {
    access_ = scene_file_access(options_, canonical);
    scene_.at = {file, 1, 1};
    scene_.files.push_back(file);
    files_.push_back({Lexer(file), std::move(canonical), nullptr, {}});
    parse_statements();
    return std::move(scene_);
}

// SCENE: {STATEMENT}   (directives and macro calls may come anywhere: the token stream runs them)
// STATEMENT: camera {..} | default {..} | global_settings {..} | background { COLOR } | sky_sphere {..}
//   | fog {..} | media {..} | rainbow {..} | OBJECT   (light_source among the objects)
inline void Parser::parse_statements() {
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
                    warn(t.location, "this camera replaces the one at " + position_in(scene_.camera->at, t.location));
                scene_.camera = parse_camera(next());
                continue;
            }
            // DEFAULT: default { ... }, POV-Ray's old spelling of #default.
            if (w == "default") {
                directive_default(next());
                continue;
            }
            if (w == "global_settings") {
                parse_global_settings(next());
                continue;
            }
            // BACKGROUND: background { COLOR }: the sky's colour where no sky_sphere covers it
            if (w == "background") {
                const Token kw = next();
                open_block(kw);
                scene_.background = parse_color("the background colour");
                close_block(kw, "nothing more");
                continue;
            }
            if (w == "sky_sphere") {
                parse_sky_sphere(next());
                continue;
            }
            // FOG: fog { ... }, one more fog over the others (parser/fog.hpp)
            if (w == "fog") {
                scene_.fogs.push_back(parse_fog_block(next()));
                continue;
            }
            // MEDIA: media { ... }, atmospheric, filling the space outside objects (parser/media.hpp)
            if (w == "media") {
                scene_.media.push_back(parse_media_block(next()));
                continue;
            }
            if (w == "rainbow") {
                skip_effect(next());
                continue;
            }
            if (one_of(w, {"photons", "radiosity"}))
                fail(t.location, "`" + w + "` is not supported by photon here: it belongs in `global_settings`");
            if (is_object_keyword(w)) {
                Object obj = parse_object(next());
                if (!std::holds_alternative<LightSource>(obj.shape)) obj.default_texture = default_texture_;
                primitives += obj.primitives;
                if (primitives > options_.max_primitives)
                    fail(t.location, "the scene is too large: more than " + std::to_string(options_.max_primitives) +
                                         " objects and triangles");
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

}  // namespace photon::dsl::detail
