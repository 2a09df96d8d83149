// SPDX-License-Identifier: MIT
// One render shared by N ranks (parallel/work_share.hpp) gives the one-process image bit for bit,
// in every mode. The ranks here are threads of this process exchanging through shared memory, so
// the library's splitting and reassembly are checked without MPI; tests/distributed runs the
// same through mpirun.
#include <catch2/catch.hpp>

#include "../../examples/cornell_box.hpp"
#include "film_compare.hpp"

#include <barrier>
#include <cmath>
#include <photon/photon.hpp>
#include <thread>

using namespace photon;

namespace {

/// `ranks` threads' exchange board: each all_gather posts its bytes, waits for all, copies all.
class ThreadRanks {
public:
    explicit ThreadRanks(unsigned ranks) : ranks_(ranks), board_(ranks), sync_(ranks) {}

    class Share final : public WorkShare {
    public:
        Share(ThreadRanks& all, unsigned rank) : all_(all), rank_(rank) {}
        [[nodiscard]] unsigned rank() const noexcept override { return rank_; }
        [[nodiscard]] unsigned ranks() const noexcept override { return all_.ranks_; }
        [[nodiscard]] std::vector<std::vector<std::byte>> all_gather(std::span<const std::byte> mine, const char*) override {
            all_.board_[rank_].assign(mine.begin(), mine.end());
            all_.sync_.arrive_and_wait();
            std::vector<std::vector<std::byte>> out = all_.board_;
            all_.sync_.arrive_and_wait();  // nobody posts the next exchange before all have read this one
            bytes += mine.size();
            return out;
        }
        std::size_t bytes = 0;

    private:
        ThreadRanks& all_;
        unsigned rank_;
    };

    /// render() on every rank; every rank's result.
    template <class SceneT>
    std::vector<RenderResult> render_all(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera,
                                         RenderSettings settings, std::vector<std::size_t>* bytes = nullptr) {
        std::vector<RenderResult> results(ranks_);
        std::vector<Share> shares;
        for (unsigned r = 0; r < ranks_; ++r) shares.emplace_back(*this, r);
        {
            std::vector<std::jthread> threads;
            for (unsigned r = 0; r < ranks_; ++r)
                threads.emplace_back([&, r, settings]() mutable {
                    settings.share = &shares[r];
                    results[r] = render(scene, camera, settings);
                });
        }
        if (bytes)
            for (const Share& s : shares) bytes->push_back(s.bytes);
        return results;
    }

private:
    unsigned ranks_;
    std::vector<std::vector<std::byte>> board_;
    std::barrier<> sync_;
};

RenderSettings small(RenderMode mode) {
    RenderSettings s;
    s.mode = mode;
    s.width = 40;
    s.height = 30;
    s.shadow_samples = 2;
    s.samples_per_pixel = 4;
    s.global_photons = 30'000;  // 30 blocks of 1024: an uneven deal among 2 and 3 ranks
    s.caustic_photons = 10'000;
    s.final_gather_rays = 16;  // with the irradiance cache and the precomputed irradiance (defaults)
    s.sppm_passes = 3;
    s.sppm_photons_per_pass = 5'000;
    s.threads = 1;
    return s;
}

}  // namespace

TEST_CASE("ranks sharing a render give the one-process image and statistics in every mode", "[render]") {
    const auto box = cornell::make_cornell_box<float>();
    for (const RenderMode mode : {RenderMode::pm, RenderMode::rt, RenderMode::sppm, RenderMode::reference}) {
        RenderSettings s = small(mode);
        // A budget: reference renders rounds, each judged from every rank's rows; sppm judges
        // every pass from every rank's pixels (its 3 passes do not reach 0.1%).
        if (mode == RenderMode::reference) s.target_error = 0.5;
        if (mode == RenderMode::sppm) s.target_error = 0.001;
        s.threads = 2;
        const RenderResult one = render(box.scene, box.camera, s);
        s.threads = 1;
        for (unsigned ranks : {1u, 2u, 3u}) {
            INFO("mode " << to_string(mode) << ", " << ranks << " ranks");
            std::vector<std::size_t> bytes;
            const std::vector<RenderResult> all = ThreadRanks(ranks).render_all(box.scene, box.camera, s, &bytes);
            for (const RenderResult& r : all) {
                CHECK(identical(one.film, r.film));
                CHECK(identical(one.error_image, r.error_image));
                CHECK(r.stats.rays.total() == one.stats.rays.total());
                CHECK(r.stats.global.stored == one.stats.global.stored);
                CHECK(r.stats.global.rays == one.stats.global.rays);
                CHECK(r.stats.cache_records == one.stats.cache_records);
                CHECK(r.stats.sppm.photon_hits == one.stats.sppm.photon_hits);
            }
            // Every rank sent its share of the work.
            if (ranks > 1)
                for (std::size_t b : bytes) CHECK(b > 0);
        }
        if (mode == RenderMode::pm) {
            CHECK(one.stats.cache_records > 0);  // the irradiance cache was built, so it was shared
            CHECK(one.stats.global.stored > 0);
        }
    }
}

TEST_CASE("ranks sharing an adaptive render give the one-process image and sample counts", "[render]") {
    // Each pixel decides from its own samples: no exchange, whichever rank renders it.
    const auto box = cornell::make_cornell_box<float>();
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm}) {
        RenderSettings s = small(mode);
        s.aa_threshold = 0.1f;
        s.aa_max_samples = 16;
        const RenderResult one = render(box.scene, box.camera, s);
        REQUIRE(one.stats.pixel_samples.most > s.samples_per_pixel);
        for (unsigned ranks : {2u, 3u}) {
            INFO("mode " << to_string(mode) << ", " << ranks << " ranks");
            for (const RenderResult& r : ThreadRanks(ranks).render_all(box.scene, box.camera, s)) {
                CHECK(identical(one.film, r.film));
                CHECK(r.stats.pixel_samples.pixels == one.stats.pixel_samples.pixels);
                CHECK(r.stats.pixel_samples.samples == one.stats.pixel_samples.samples);
                CHECK(r.stats.pixel_samples.most == one.stats.pixel_samples.most);
            }
        }
    }
}

TEST_CASE("the hashed deal evens out a cost that follows the interleave, and its lists come back whole", "[render]") {
    // Units of a row of even width whose dear ones are every second (the irradiance cache's last
    // level): round-robin gives every dear unit to rank 0 of 2, the hash about half to each.
    constexpr std::size_t units = 10'000;
    for (unsigned ranks : {2u, 3u}) {
        ThreadRanks all(ranks);
        std::vector<std::size_t> dear_interleaved(ranks), dear_hashed(ranks);
        for (unsigned r = 0; r < ranks; ++r) {
            const ThreadRanks::Share share(all, r);
            for (std::size_t u = 0; u < units; u += 2) {
                dear_interleaved[r] += owns(&share, u);
                dear_hashed[r] += owns(&share, u, Deal::hashed);
            }
        }
        std::size_t total = 0;
        for (unsigned r = 0; r < ranks; ++r) {
            INFO(ranks << " ranks, rank " << r);
            total += dear_hashed[r];
            CHECK(std::abs(double(dear_hashed[r]) * ranks / (units / 2) - 1.0) < 0.05);
        }
        CHECK(total == units / 2);  // every unit has exactly one owner
        if (ranks == 2) CHECK(dear_interleaved[0] == units / 2);
    }
    // Each rank fills the lists it owns under the hash; share_lists puts every list back in place.
    for (unsigned ranks : {2u, 3u}) {
        ThreadRanks all(ranks);
        std::vector<std::vector<std::vector<int>>> lists(ranks, std::vector<std::vector<int>>(101));
        {
            std::vector<std::jthread> threads;
            for (unsigned r = 0; r < ranks; ++r)
                threads.emplace_back([&, r] {
                    ThreadRanks::Share share(all, r);
                    for (std::size_t u = 0; u < lists[r].size(); ++u)
                        if (owns(&share, u, Deal::hashed)) lists[r][u].assign(u % 4, int(u));  // some empty
                    share_lists(&share, lists[r], "test", Deal::hashed);
                });
        }
        for (unsigned r = 0; r < ranks; ++r)
            for (std::size_t u = 0; u < lists[r].size(); ++u) {
                INFO(ranks << " ranks, rank " << r << ", unit " << u);
                CHECK(lists[r][u] == std::vector<int>(u % 4, int(u)));
            }
    }
}
