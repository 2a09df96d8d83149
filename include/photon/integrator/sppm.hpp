// SPDX-License-Identifier: MIT
#pragma once
// Stochastic progressive photon mapping (Hachisuka and Jensen 2009, "Stochastic Progressive
// Photon Mapping"): the consistent judge of the other modes. Each pass traces one camera path
// per pixel to a visible point (sppm_visible_points.hpp) and a fresh set of photons; every pixel
// keeps a radius R, a photon count N and a flux tau, and after each pass
//   N' = N + alpha M,   R' = R sqrt((N + alpha M) / (N + M)),   tau' = (tau + Phi_M) R'^2 / R^2
// for the M photons (of flux Phi_M) found within R of its visible point. R shrinks to 0 while N
// grows without bound, so bias and noise both vanish: unlike the two-pass photon map, any path
// (L S+ D S+ E from a point light included, which the path tracer cannot find) converges to the
// right answer. Direct light comes from shadow rays; photons supply only light that bounced at
// least once after leaving the light, so nothing is counted twice.
//
// Deterministic for any thread count: photons are traced in fixed blocks with one random stream
// per photon and pass, concatenated in block order into a kd-tree; each pixel gathers from it in
// the tree's order, summing in double, with its own stream per pass.
//
// The error estimate: even and odd passes feed two independent progressive states, two
// half-images whose difference estimates the noise of their mean, the image
// (film/error_estimate.hpp). The image is two independent sppm renders of half the passes each,
// averaged: as noisy as one of all the passes, and its radii a little larger (the bias shrinks
// as passes^-1/6, so half the passes leave it 12% larger).

#include <array>
#include <chrono>
#include <functional>
#include <mutex>
#include <vector>

#include "../film/error_estimate.hpp"
#include "../film/film.hpp"
#include "../geometry/offset.hpp"
#include "../light/light.hpp"
#include "../parallel/parallel_for.hpp"
#include "../parallel/work_share.hpp"
#include "../photonmap/kdtree.hpp"
#include "../scene/media_segment.hpp"
#include "../tracing/light_allocation.hpp"
#include "../tracing/photon_hit.hpp"
#include "memory_budget.hpp"
#include "sppm_visible_points.hpp"

namespace photon {

/// The fraction of a pass's photons each pixel keeps (Hachisuka and Jensen's alpha): the radius
/// shrinks as n^-(1 - alpha)/2 with passes; 2/3 is their choice, balancing noise against bias.
inline constexpr double sppm_alpha = 2.0 / 3.0;

/// Automatic initial radius, in pixel footprints at the pixel's first visible point: blur of
/// about what the image resolves anyway, at any scene scale and resolution (docs/design.md).
inline constexpr double sppm_radius_in_pixels = 2.0;

/// A photon where it met a diffuse surface after at least one bounce.
struct SppmPhoton {
    Vec3<float> position;
    Rgb<float> power;
    Vec3<float> side;  ///< unit surface normal on the side the photon arrived from
};

template <> struct point_traits<SppmPhoton> {
    struct payload_type {
        Rgb<float> power;
        Vec3<float> side;
    };
    [[nodiscard]] static Vec3<float> position(const SppmPhoton& p) noexcept { return p.position; }
    [[nodiscard]] static payload_type payload(const SppmPhoton& p) noexcept { return {p.power, p.side}; }
};

/// The statistics of one pixel, over all passes so far (double: thousands of passes add up).
struct SppmPixel {
    double radius = 0;  ///< 0 until the pixel's first visible point
    double photons = 0;  ///< N
    Rgb<double> flux{0.0};    ///< tau
    Rgb<double> direct{0.0};  ///< sum over passes of the shadow-ray light
};

/// Called after every pass with the number of passes done and the image they give.
using SppmPassCallback = std::function<void(unsigned passes, const Film& film)>;

namespace detail {

constexpr std::size_t sppm_photon_block = 1024;  ///< photons per work unit, fixed for determinism
constexpr std::uint64_t sppm_photon_salt = 0x7370706d70686fULL, sppm_camera_salt = 0x7370706d63616dULL,
                        sppm_scramble_salt = 0x7370706d736372ULL;

/// The seed of pass `pass`'s random streams.
[[nodiscard]] constexpr std::uint64_t sppm_pass_seed(std::uint64_t seed, std::uint64_t salt, unsigned pass) noexcept {
    return mix64(seed ^ salt) ^ mix64(std::uint64_t(pass) + 1);
}

/// Photon index -> light and the power each of its photons carries (a pass emits, in total, the
/// lights' power). A sky of power `environment_power` > 0 (into the scene's environment ball)
/// is light lights.size(); its `power` is 1 / its count, times each photon's own
/// (Environment::sample_photon).
template <Scalar S> struct SppmEmission {
    std::vector<std::size_t> first;
    std::vector<Rgb<S>> power;
    SppmEmission(std::span<const Light<S>> lights, std::size_t photons, double environment_power = 0) {
        const std::vector<std::size_t> counts = photons_per_light<S>(lights, photons, {}, {}, environment_power);
        std::size_t at = 0;
        for (std::size_t l = 0; l < counts.size(); ++l) {
            first.push_back(at);
            const Rgb<S> total = l < lights.size() ? light_power(lights[l]) : Rgb<S>(S(1));
            power.push_back(counts[l] ? total / S(counts[l]) : Rgb<S>(S(0)));
            at += counts[l];
        }
    }
    [[nodiscard]] std::size_t light_of(std::size_t photon) const noexcept {
        std::size_t l = 0;
        while (l + 1 < first.size() && first[l + 1] <= photon) ++l;
        return l;
    }
};

struct SppmPhotonPass {
    std::vector<SppmPhoton> hits;
    std::uint64_t rays = 0;
};

/// One pass's photons: emitted by power among the lights, followed by Russian roulette for at
/// most settings.max_photon_depth surface hits, recorded at every diffuse hit but the first.
template <class SceneT>
[[nodiscard]] SppmPhotonPass trace_sppm_photons(const SceneT& scene, const SppmEmission<typename SceneT::scalar_type>& plan,
                                                const RenderSettings& settings, unsigned pass) {
    using S = typename SceneT::scalar_type;
    const auto lights = scene.lights();
    if (plan.first.empty()) return {};  // no lights
    const std::size_t n = settings.sppm_photons_per_pass;
    const std::size_t blocks = (n + sppm_photon_block - 1) / sppm_photon_block;
    std::vector<SppmPhotonPass> out(blocks);
    const std::uint64_t seed = sppm_pass_seed(settings.seed, sppm_photon_salt, pass);
    parallel_for(blocks, 1, settings.threads, [&](std::size_t b0, std::size_t b1) {
        for (std::size_t b = b0; b < b1; ++b) {
            if (!owns(settings.share, b)) continue;  // another rank's block
            SppmPhotonPass& block = out[b];
            for (std::size_t i = b * sppm_photon_block; i < std::min(n, (b + 1) * sppm_photon_block); ++i) {
                Pcg32 rng(seed, i);
                const std::size_t l = plan.light_of(i);
                if (is_black(plan.power[l])) continue;
                const bool sky = l == lights.size();
                Ray<S> ray{};
                Rgb<S> power;
                if (sky) {
                    const Vec2<S> u_direction = rng.uniform2<S>();
                    const EnvironmentPhoton<S> p = scene.environment()->sample_photon(scene.environment_ball(), u_direction,
                                                                                      rng.uniform2<S>());
                    ray = p.ray;
                    power = plan.power[l] * p.power;
                } else {
                    const Vec3<S> dir = sample_emission_direction(lights[l], settings.emission, rng);
                    ray = Ray<S>{leaving_light(sample_emission_origin(lights[l], dir, rng.uniform2<S>()), dir), dir};
                    power = plan.power[l] * emission_weight(lights[l], dir);
                }
                for (unsigned depth = 0; depth < settings.max_photon_depth; ++depth) {
                    const auto surface = photon_intersect(scene, ray, block.rays);
                    ++block.rays;
                    if (!surface) break;
                    if (depth == 0 && !sky) power *= first_hit_scale(lights[l], surface->hit.point, ray.origin);  // the light's falloff
                    const Material<S>& material = *surface->material;
                    const Facing<S> f = facing(material, surface->hit.point, surface->hit.normal, ray.direction);
                    power *= segment_transmittance(material, f, surface->hit.t);  // absorbed inside coloured glass
                    power *= media_transmittance_seen(scene, ray, surface, &f, rng);  // dimmed by media
                    // Depth 0 is direct light, which the shadow rays of the camera pass cover.
                    if (depth > 0 && material.has_diffuse())
                        block.hits.push_back({Vec3<float>(surface->hit.point), Rgb<float>(power * shading_ratio(f)),
                                               Vec3<float>(f.normal)});
                    const PhotonScatter<S> s = russian_roulette(material, surface->hit.point, f, ray.direction, rng);
                    if (s.event == ScatterEvent::absorbed) break;
                    power *= s.weight;
                    const Vec3<S> side = s.event == ScatterEvent::transmission ? -f.normal : f.normal;
                    ray = Ray<S>{offset_origin(surface->hit.point, side, intersection_error(surface->hit.point, ray.origin)),
                                 s.direction};
                }
            }
        }
    });
    if (!single(settings.share)) {  // every rank's blocks, in block order on every rank
        std::vector<std::vector<SppmPhoton>> hits(blocks);
        std::vector<std::vector<std::uint64_t>> rays(blocks);
        for (std::size_t b = 0; b < blocks; ++b)
            if (owns(settings.share, b)) hits[b] = std::move(out[b].hits), rays[b] = {out[b].rays};
        share_lists(settings.share, hits, "sppm photons");
        share_lists(settings.share, rays, "sppm photons");
        for (std::size_t b = 0; b < blocks; ++b) out[b].hits = std::move(hits[b]), out[b].rays = rays[b].empty() ? 0 : rays[b][0];
    }
    SppmPhotonPass all;
    std::size_t total = 0;
    for (const auto& b : out) total += b.hits.size();
    all.hits.reserve(total);
    for (auto& b : out) {
        all.hits.insert(all.hits.end(), b.hits.begin(), b.hits.end());
        all.rays += b.rays;
        std::vector<SppmPhoton>().swap(b.hits);
    }
    return all;
}

/// Sums the photons within a visible point's radius that arrived on its side of the surface
/// and lie within R/2 of its tangent plane. The slab keeps photons of parallel surfaces closer
/// than R (a thin shelf over the floor, a box lid) out, yet keeps every photon of a sphere of
/// radius >= R: those lie at most R^2 / (2 rho) <= R/2 off the plane, and the ball of radius R
/// around a point of a sphere cuts exactly the area pi R^2 from it (Archimedes), so curved
/// surfaces need no correction.
struct SppmGather {
    const KdTree<SppmPhoton>& tree;
    Vec3<float> x, n;
    float radius2, slab;
    Rgb<double> power{0.0};
    std::uint64_t count = 0;

    [[nodiscard]] float max_distance2() const noexcept { return radius2; }
    void visit(std::uint32_t i, float) noexcept {
        if (std::abs(glm::dot(tree.position(i) - x, n)) > slab) return;
        const auto& p = tree.payload(i);
        if (!(glm::dot(p.side, n) > 0.0f)) return;
        power += Rgb<double>(p.power);
        ++count;
    }
};

/// The progressive update of one pixel with M photons of summed power `power` found this pass
/// at a visible point of weight `weight`.
inline void sppm_update(SppmPixel& px, std::uint64_t m, const Rgb<double>& power, const Rgb<double>& weight) noexcept {
    if (m == 0) return;
    const double n_next = px.photons + sppm_alpha * double(m);
    const double shrink2 = n_next / (px.photons + double(m));  // R'^2 / R^2
    px.flux = (px.flux + weight * power) * shrink2;
    px.photons = n_next;
    px.radius *= std::sqrt(shrink2);
}

/// The image after `passes` passes: mean direct light + tau / (pi R^2 passes). Each pass's
/// photons carry the lights' whole power, so dividing by the passes is Hachisuka and Jensen's
/// division by the photons emitted with photons of power Phi / (photons per pass).
inline Film sppm_film(const std::vector<SppmPixel>& pixels, unsigned width, unsigned height, unsigned passes) {
    Film film(width, height);
    if (passes == 0) return film;
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const SppmPixel& px = pixels[i];
        Rgb<double> l = px.direct / double(passes);
        if (px.radius > 0) l += px.flux / (pi<double> * px.radius * px.radius * double(passes));
        film.pixels()[i] = Rgb<float>(l);
    }
    return film;
}

/// The image of the two progressive states after `passes` passes (even passes in the first):
/// their mean weighted by their passes, and its error estimate when both have one.
struct SppmImage {
    Film film;
    ErrorEstimate error;
    Film error_film;  ///< per-pixel |A - B| / 2, when both states have a pass
};

[[nodiscard]] inline SppmImage sppm_image(const std::array<std::vector<SppmPixel>, 2>& halves, unsigned width,
                                          unsigned height, unsigned passes, bool with_error_film) {
    const unsigned even = (passes + 1) / 2, odd = passes / 2;
    SppmImage image;
    if (odd == 0) {
        image.film = sppm_film(halves[0], width, height, even);
        return image;
    }
    const Film a = sppm_film(halves[0], width, height, even), b = sppm_film(halves[1], width, height, odd);
    image.film = combine_halves(a, b, double(even), double(odd));
    image.error = estimate_error(a, b);
    if (with_error_film) image.error_film = error_image(a, b);
    return image;
}

}  // namespace detail

/// Renders by stochastic progressive photon mapping: up to settings.sppm_passes passes of one
/// camera path per pixel and settings.sppm_photons_per_pass photons, fewer when the budget
/// (settings.time_limit, settings.target_error) is met first, reporting RenderPhase::sppm_pass and
/// settings.on_pass after each; `on_pass`, if given, sees the image after every pass. Cancelling
/// stops after the current pass (stats.partial). Fills stats.sppm, stats.error, stats.stopped_by,
/// stats.rays and the times, `*error_film` (if given) with the per-pixel error estimate, and
/// `*halves` (if given) with the two half-images (even and odd passes; pm's error estimate
/// compares its image with them, integrator/pm_error.hpp).
template <class SceneT>
[[nodiscard]] Film render_sppm(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera,
                               const RenderSettings& settings, RenderStats& stats, const SppmPassCallback& on_pass = {},
                               Film* error_film = nullptr, std::array<Film, 2>* halves_out = nullptr) {
    using S = typename SceneT::scalar_type;
    validate(settings);
    const auto start = std::chrono::steady_clock::now();
    const unsigned width = settings.width, height = settings.height;
    std::array<std::vector<SppmPixel>, 2> halves;  // even and odd passes' progressive states
    for (auto& h : halves) h.resize(std::size_t(width) * height);
    const bool sky = scene.has_environment_light() && scene.environment_ball().radius > S(0);
    const detail::SppmEmission<S> plan(scene.lights(), settings.sppm_photons_per_pass,
                                       sky ? double(scene.environment()->power_into(scene.environment_ball())) : 0.0);
    const PixelSpread<S> spread = camera.pixel_spread(width, height);
    auto seconds_since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
    stats.stopped_by = "passes done";
    unsigned pass = 0;
    double last_pass_seconds = 0;
    while (pass < settings.sppm_passes) {
        // Rank 0's cancel flag decides for every rank, as its clock does below.
        if (agree(settings.share, settings.cancel && settings.cancel->load(std::memory_order_relaxed), "sppm cancel")) {
            stats.partial = true;
            stats.stopped_by = "cancelled";
            break;
        }
        // Stop before a pass that would end past the time limit (after two: an image with an
        // error estimate comes first).
        // Rank 0's clock decides for every rank (parallel/work_share.hpp).
        if (agree(settings.share, settings.time_limit > 0 && pass >= 2 && seconds_since(start) + last_pass_seconds > settings.time_limit,
                  "sppm budget")) {
            stats.stopped_by = "time limit";
            break;
        }
        const auto pass_start = std::chrono::steady_clock::now();
        std::vector<SppmPixel>& pixels = halves[pass % 2];
        detail::SppmPhotonPass photons = detail::trace_sppm_photons(scene, plan, settings, pass);
        const KdTree<SppmPhoton> tree(std::span<const SppmPhoton>(photons.hits), {.threads = settings.threads});
        stats.sppm.photon_hits += photons.hits.size();
        stats.sppm.photon_rays += photons.rays;
        std::vector<SppmPhoton>().swap(photons.hits);
        stats.sppm.photon_seconds += seconds_since(pass_start);

        const auto gather_start = std::chrono::steady_clock::now();
        const std::uint64_t camera_seed = detail::sppm_pass_seed(settings.seed, detail::sppm_camera_salt, pass);
        std::mutex merge;
        parallel_for(height, 1, settings.threads, [&](std::size_t y0, std::size_t y1) {
            ShadingContext ctx;
            for (std::size_t y = y0; y < y1; ++y) {
                if (!owns(settings.share, y)) continue;  // another rank's row
                for (unsigned x = 0; x < width; ++x) {
                    if (!in_pixel_subset(x, unsigned(y), settings.sppm_pixel_stride)) continue;  // a judge's subset
                    const std::uint64_t index = std::uint64_t(y) * width + x;
                    SppmPixel& px = pixels[index];
                    // Each half runs its own scrambled (0,2)-sequence over its own passes: one
                    // sequence split by pass parity would put the halves' samples in different
                    // parts of the pixel (its first bit is the parity), and their difference at
                    // edges would read as noise.
                    Pcg32 scramble(settings.seed ^ detail::sppm_scramble_salt, index);
                    std::uint32_t sx = scramble.next_u32(), sy = scramble.next_u32();
                    if (pass % 2 == 1) sx = scramble.next_u32(), sy = scramble.next_u32();
                    const Vec2<double> jitter = progressive_pixel_sample(pass / 2, sx, sy);
                    ctx.rng = Pcg32(camera_seed, index);
                    ++ctx.rays.camera;
                    const auto ray = camera.ray(S((double(x) + jitter.x) / width), S((double(y) + jitter.y) / height),
                                                lens_sample(camera, ctx.rng));
                    if (!ray) continue;  // outside the projection: black, as POV-Ray shows it
                    const CameraPath<S> path = trace_camera_path(scene, *ray, settings, ctx);
                    px.direct += Rgb<double>(path.direct);
                    if (!path.point) continue;
                    const VisiblePoint<S>& vp = *path.point;
                    if (px.radius == 0)
                        px.radius = settings.sppm_initial_radius > 0 ? double(settings.sppm_initial_radius)
                                                                     : sppm_radius_in_pixels *
                                                                           (double(spread.size) + double(spread.angle) * double(vp.path_length));
                    if (tree.empty() || !(px.radius > 0)) continue;
                    const float r = float(px.radius);
                    detail::SppmGather gather{tree, Vec3<float>(vp.position), Vec3<float>(vp.normal), r * r, 0.5f * r};
                    tree.search(gather.x, gather);
                    detail::sppm_update(px, gather.count, gather.power, Rgb<double>(vp.weight));
                }
            }
            const std::lock_guard lock(merge);
            stats.rays += ctx.rays;
        });
        stats.sppm.gather_seconds += seconds_since(gather_start);
        stats.sppm.emitted += settings.sppm_photons_per_pass;
        stats.sppm.passes = ++pass;
        last_pass_seconds = seconds_since(pass_start);
        if (settings.progress) settings.progress(RenderPhase::sppm_pass, double(pass) / double(settings.sppm_passes));
        const bool wants_error = settings.target_error > 0 || settings.on_pass;
        // Every rank makes the same exchanges: rank 0's callbacks decide for all.
        if (!agree(settings.share, on_pass || wants_error, "sppm budget")) continue;
        share_runs(settings.share, std::span(pixels), width, "sppm pixels");  // the other half is whole since the last pass
        const detail::SppmImage image = detail::sppm_image(halves, width, height, pass, false);
        if (on_pass) on_pass(pass, image.film);
        if (settings.on_pass) settings.on_pass({pass, settings.sppm_passes, seconds_since(start), image.error});
        if (settings.target_error > 0 && image.error.available && image.error.relative_rmse <= settings.target_error) {
            stats.stopped_by = "target error";
            break;
        }
    }
    for (auto& h : halves) share_runs(settings.share, std::span(h), width, "sppm pixels");
    double radius_sum = 0;
    std::size_t with_radius = 0;
    for (const auto& h : halves)
        for (const SppmPixel& px : h)
            if (px.radius > 0) radius_sum += px.radius, ++with_radius;
    stats.sppm.mean_radius = with_radius ? radius_sum / double(with_radius) : 0.0;
    detail::SppmImage image = detail::sppm_image(halves, width, height, pass, error_film != nullptr);
    stats.error = image.error;
    if (error_film) *error_film = std::move(image.error_film);
    if (halves_out)
        *halves_out = {detail::sppm_film(halves[0], width, height, (pass + 1) / 2), detail::sppm_film(halves[1], width, height, pass / 2)};
    stats.render_seconds = seconds_since(start);
    return std::move(image.film);
}

}  // namespace photon
