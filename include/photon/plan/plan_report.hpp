// SPDX-License-Identifier: MIT
#pragma once
// The light-path plan as a few lines of text, for `photon check`, every render and embedders:
// the path classes, the maps with their photons, the passes, and every dropped item's reason.

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <unordered_map>
#include <vector>

#include "effects_plan.hpp"

namespace photon {

/// The dropped items as lines a reader can take in: a scene of thousands of objects can drop
/// caustic photons at each for one reason, so more than three items with the same `why` make one
/// line naming the first three ("caustic photons at object 7 (sphere), object 8 (sphere), object
/// 9 (cone) and 4310 more: WHY"), and past `most` lines those with the most items are kept, the
/// last saying how many more there are (EffectsPlan::dropped holds every item).
[[nodiscard]] inline std::vector<std::string> dropped_lines(const std::vector<DroppedEffect>& dropped,
                                                            std::size_t most = 24) {
    struct Group {
        std::string why;
        std::vector<std::string> whats;
    };
    std::vector<Group> groups;  // in the order of their first items
    std::unordered_map<std::string, std::size_t> group_of;
    for (const DroppedEffect& d : dropped) {
        const auto [it, added] = group_of.try_emplace(d.why, groups.size());
        if (added) groups.push_back({d.why, {}});
        groups[it->second].whats.push_back(d.what);
    }
    std::vector<std::pair<std::size_t, std::string>> counted;  // items on the line, the line
    for (const Group& g : groups) {
        if (g.whats.size() <= 3) {
            for (const std::string& what : g.whats) counted.emplace_back(1, DroppedEffect{what, g.why}.line());
            continue;
        }
        // The words the items share up to their subject ("caustic photons at "), said once.
        const std::string& first = g.whats.front();
        std::size_t shared = first.size();
        for (const std::string& w : g.whats)
            shared = std::min(shared, std::size_t(std::mismatch(first.begin(), first.begin() + std::min(first.size(), w.size()),
                                                                 w.begin()).first - first.begin()));
        std::size_t keep = 0;
        for (const char* joint : {" at ", " from "}) {
            const std::size_t at = first.rfind(joint, shared);
            if (at != std::string::npos && at + std::strlen(joint) <= shared) keep = std::max(keep, at + std::strlen(joint));
        }
        std::string line = first;
        for (std::size_t i = 1; i < 3; ++i) line += ", " + g.whats[i].substr(keep);
        line += " and " + std::to_string(g.whats.size() - 3) + " more";
        counted.emplace_back(g.whats.size(), DroppedEffect{line, g.why}.line());
    }
    if (counted.size() > most)  // the lines that say the most first
        std::stable_sort(counted.begin(), counted.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<std::string> lines;
    for (std::size_t i = 0; i < counted.size() && (counted.size() <= most || i + 1 < most); ++i)
        lines.push_back(counted[i].second);
    if (counted.size() > most)
        lines.push_back("and " + std::to_string(counted.size() - lines.size()) + " more lines (" +
                        std::to_string(dropped.size()) + " items dropped in all; EffectsPlan::dropped lists each)");
    return lines;
}

/// One line per item, each "LABEL  text" with the labels padded to one width.
[[nodiscard]] inline std::vector<std::string> plan_lines(const EffectsPlan& plan, const char* mode) {
    std::vector<std::string> lines;
    auto line = [&](const char* label, const std::string& text) {
        std::string l(label);
        l.resize(16, ' ');
        lines.push_back(l + text);
    };
    auto verdict = [](const PathClassPlan& p, const std::string& yes) {
        return p.present ? (yes.empty() ? std::string("yes") : "yes, " + yes) : "no: " + p.reason;
    };
    std::string carriers;
    const auto& names = plan.caustic_object_names;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i == 4) {
            carriers += " and " + std::to_string(names.size() - i) + " more";
            break;
        }
        carriers += (i ? ", " : "from ") + names[i];
    }
    line("L D E", "direct light: " + verdict(plan.direct, ""));
    line("L D D+ E", "indirect light: " + verdict(plan.indirect, ""));
    line("L S+ D E", "caustics: " + verdict(plan.caustics, carriers));
    line("L (S|D)* S+ E", "seen in mirrors and glass: " + verdict(plan.specular_view, ""));
    if (!plan.planned) {
        line("passes", std::string("mode ") + mode + "'s own; the plan drops nothing in this mode");
        return lines;
    }
    std::string maps;
    if (plan.global_pass)
        maps += "global " + std::to_string(plan.global_photons) + " photons" +
                (plan.environment_photons ? " (" + std::to_string(plan.environment_photons) + " from the sky)" : "") +
                (plan.global_for_unaimed_caustics_only ? " (for unaimed caustics only)" : "");
    if (plan.caustic_pass) maps += (maps.empty() ? "" : ", ") + ("caustic " + std::to_string(plan.caustic_photons) + " photons");
    line("maps", maps.empty() ? "none" : maps);
    if (plan.lights.size() > 8 && (plan.global_pass || plan.caustic_pass)) {
        // Too many to list: the range, and the light that gets the most.
        std::size_t most = 0, least = 0, silent = 0;
        for (std::size_t l = 0; l < plan.lights.size(); ++l) {
            const std::size_t n = plan.lights[l].global_photons, m = plan.lights[most].global_photons;
            if (n > m) most = l;
            if (n < plan.lights[least].global_photons) least = l;
            silent += plan.lights[l].emits ? 0 : 1;
        }
        line("photons/light", std::to_string(plan.lights.size()) + " lights (" + std::to_string(silent) +
                                  " silent): global photons from " + std::to_string(plan.lights[least].global_photons) +
                                  " (light " + std::to_string(least) + ") to " +
                                  std::to_string(plan.lights[most].global_photons) + " (light " + std::to_string(most) + ")");
    } else if (plan.lights.size() > 1 && (plan.global_pass || plan.caustic_pass)) {
        std::string shares;
        for (std::size_t l = 0; l < plan.lights.size(); ++l) {
            const LightPlan& lp = plan.lights[l];
            shares += (l ? "; " : "") + std::to_string(l) + ": " +
                      (lp.emits ? std::to_string(lp.global_photons) + " + " + std::to_string(lp.caustic_photons) : "none");
        }
        line("photons/light", shares + " (global + caustic)");
    }
    if (!plan.global_light_shares.empty()) {
        std::size_t unseen = 0;
        for (const LightPlan& lp : plan.lights) {
            if (lp.visible_fraction < 0) continue;
            unseen += lp.visible_fraction == 0 ? 1 : 0;
        }
        char text[200];
        std::snprintf(text, sizeof text,
                      "global photons by the power reaching what the camera sees (a pilot of %u photons per light; "
                      "each light keeps %.0f%% of its share by power); %zu of %zu lights seen reaching nothing visible",
                      plan.pilot.photons_per_light, 100.0 * plan.pilot.floor, unseen, plan.lights.size());
        line("light shares", text);
    }
    if (!plan.caustic_pilot.empty()) {
        // Each target's part of the caustic light the pilot saw land in view (at most four named).
        double total = 0.0;
        for (const auto& m : plan.caustic_pilot) total += m.seen;
        std::string parts;
        for (std::size_t k = 0; k < plan.caustic_pilot.size() && k < 4; ++k) {
            const auto& m = plan.caustic_pilot[k];
            std::string name = "object " + std::to_string(m.object);
            for (std::size_t i = 0; i < plan.caustic_objects.size(); ++i)
                if (plan.caustic_objects[i] == m.object && i < names.size()) name = names[i];
            char share[32];
            std::snprintf(share, sizeof share, " %.1f%%", total > 0.0 ? 100.0 * m.seen / total : 0.0);
            parts += (k ? ", " : "") + name + share;
        }
        if (plan.caustic_pilot.size() > 4) parts += " and " + std::to_string(plan.caustic_pilot.size() - 4) + " more";
        line("caustic aim", "a pilot of " + std::to_string(plan.caustic_pilot[0].photons) +
                                " photons per target; of the caustic light landing in view: " + parts);
    }
    std::string passes;
    auto pass = [&](bool runs, const char* name) {
        if (runs) passes += (passes.empty() ? "" : ", ") + std::string(name);
    };
    pass(plan.caustic_pass, "caustic photons");
    pass(plan.global_pass, "global photons");
    pass(plan.precomputed_irradiance, "precomputed irradiance");
    pass(plan.irradiance_cache, "irradiance cache");
    pass(plan.final_gather, "final gather");
    line("passes", passes.empty() ? "shadow rays and ray tracing only" : passes);
    for (const std::string& d : dropped_lines(plan.dropped)) line("dropped", d);
    return lines;
}

}  // namespace photon
