// The volumetric model on the CPU (render/volume_composite.hpp), against closed forms: a slab's
// exp(-tau d), in-scattering a L^s (1 - e^{-tau d}), overlapping media mixing tau and albedo,
// the eye inside volumes, and the numerical extremes (tau -> 0, tau = 1e6, zero-length
// segments, entries and exits at one depth in either order, nesting past the limit).
#include "render/volume_composite.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace strata;

namespace {

VolumeFragment boundary(double distance, int object, const VolumeMedium& medium, bool entry) {
    VolumeFragment f;
    f.distance = distance;
    f.object = object;
    f.medium = &medium;
    f.entry = entry;
    return f;
}

VolumeMedium medium(glm::vec3 tau, glm::vec3 albedo) { return {tau, tau * albedo}; }

const glm::vec3 kBackground(0.25f, 0.5f, 1.0f);
constexpr float kLs = 0.8f;  // L^s, any positive value

}  // namespace

TEST_CASE("segmentIntegral is (1 - e^{-tau d}) / tau without cancellation") {
    CHECK(segmentIntegral(0.0, 2.5) == 2.5);
    // tau d = 1e-12: the naive (1 - exp(-x)) / tau loses every digit; the series keeps them.
    CHECK(segmentIntegral(1e-12, 1.0) == doctest::Approx(1.0 - 0.5e-12).epsilon(1e-15));
    CHECK(segmentIntegral(1.0, 1.0) == doctest::Approx(1.0 - std::exp(-1.0)).epsilon(1e-15));
    CHECK(segmentIntegral(1e6, 1.0) == doctest::Approx(1e-6).epsilon(1e-15));
    CHECK(segmentIntegral(1e6, 0.0) == 0.0);
}

TEST_CASE("a slab of thickness d lets exp(-tau d) through and scatters a L^s (1 - e^{-tau d})") {
    const glm::vec3 tau(0.5f, 2.0f, 7.0f), albedo(0.0f, 0.5f, 1.0f);
    const VolumeMedium m = medium(tau, albedo);
    const double d = 0.75;
    const std::vector<VolumeFragment> list = {boundary(2.0, 0, m, true), boundary(2.0 + d, 0, m, false)};
    const VolumeResult r = compositeVolumes(list, MediumSet(), 10.0, kBackground, kLs);
    for (int k = 0; k < 3; ++k) {
        const double t = std::exp(-double(tau[k]) * d);
        CHECK(r.transmittance[k] == doctest::Approx(t).epsilon(1e-6));
        CHECK(r.color[k] == doctest::Approx(albedo[k] * kLs * (1.0 - t) + t * kBackground[k]).epsilon(1e-6));
    }
    CHECK(r.nestingOverflow == 0);
}

TEST_CASE("overlapping volumes add tau and mix albedo by tau; the result does not depend on which is which") {
    // A over [1, 3], B over [2, 4]: A alone, then A and B (tau_A + tau_B, albedo weighted by
    // tau), then B alone.
    const VolumeMedium a = medium(glm::vec3(1.0f), glm::vec3(0.2f)), b = medium(glm::vec3(3.0f), glm::vec3(0.9f));
    const std::vector<VolumeFragment> list = {boundary(1, 0, a, true), boundary(2, 1, b, true), boundary(3, 0, a, false),
                                              boundary(4, 1, b, false)};
    const VolumeResult r = compositeVolumes(list, MediumSet(), 10.0, glm::vec3(0.0f), kLs);
    auto segment = [](double tau, double albedo, double len, double& color, double& t) {
        color += t * albedo * kLs * (1.0 - std::exp(-tau * len));
        t *= std::exp(-tau * len);
    };
    double color = 0.0, t = 1.0;
    segment(1.0, 0.2, 1.0, color, t);
    segment(4.0, (1.0 * 0.2 + 3.0 * 0.9) / 4.0, 1.0, color, t);
    segment(3.0, 0.9, 1.0, color, t);
    CHECK(r.color.g == doctest::Approx(color).epsilon(1e-6));
    CHECK(r.transmittance.g == doctest::Approx(t).epsilon(1e-6));
}

TEST_CASE("entries and exits at one depth: zero-length segments in any order") {
    const VolumeMedium a = medium(glm::vec3(2.0f), glm::vec3(0.5f)), b = medium(glm::vec3(5.0f), glm::vec3(0.1f));
    // A zero-thickness object (its entry and exit at one depth, either first) is invisible.
    for (bool exitFirst : {false, true}) {
        CAPTURE(exitFirst);
        std::vector<VolumeFragment> list = {boundary(3.0, 0, a, !exitFirst), boundary(3.0, 0, a, exitFirst)};
        const VolumeResult r = compositeVolumes(list, MediumSet(), 10.0, kBackground, kLs);
        CHECK(r.color == kBackground);
        CHECK(r.transmittance == glm::vec3(1.0f));
    }
    // Touching objects: A's exit and B's entry at one depth, in both orders, give one image.
    const std::vector<VolumeFragment> ab = {boundary(1, 0, a, true), boundary(2, 0, a, false), boundary(2, 1, b, true),
                                            boundary(3, 1, b, false)};
    const std::vector<VolumeFragment> ba = {boundary(1, 0, a, true), boundary(2, 1, b, true), boundary(2, 0, a, false),
                                            boundary(3, 1, b, false)};
    const VolumeResult r1 = compositeVolumes(ab, MediumSet(), 10.0, kBackground, kLs);
    const VolumeResult r2 = compositeVolumes(ba, MediumSet(), 10.0, kBackground, kLs);
    CHECK(r1.color == r2.color);
    CHECK(r1.transmittance.r == doctest::Approx(std::exp(-2.0 - 5.0)).epsilon(1e-6));
}

TEST_CASE("the eye inside one, two or all volumes: the first segment starts at the eye") {
    const VolumeMedium a = medium(glm::vec3(1.0f), glm::vec3(0.0f)), b = medium(glm::vec3(2.0f), glm::vec3(0.0f)),
                       c = medium(glm::vec3(4.0f), glm::vec3(0.0f));
    // Exits of A at 0.5, B at 1.0, C at 2.0; the eye is inside `inside` of them. A volume the eye
    // is outside of would be entered before its exit; here its exit alone leaves it at -1 (never
    // counted), so only the volumes around the eye attenuate.
    const std::vector<VolumeFragment> exits = {boundary(0.5, 0, a, false), boundary(1.0, 1, b, false),
                                               boundary(2.0, 2, c, false)};
    for (int inside = 1; inside <= 3; ++inside) {
        CAPTURE(inside);
        MediumSet eye;
        double optical = 0.0;
        const VolumeMedium* media[3] = {&a, &b, &c};
        const double ends[3] = {0.5, 1.0, 2.0};
        for (int i = 0; i < inside; ++i) {
            eye.cross(i, *media[i], 1);
            optical += double(media[i]->tau.r) * ends[i];
        }
        const VolumeResult r = compositeVolumes(exits, eye, 10.0, kBackground, kLs);
        CHECK(r.transmittance.r == doctest::Approx(std::exp(-optical)).epsilon(1e-6));
    }
}

TEST_CASE("the extremes: tau 0 is free space, tau 1e6 is opaque, albedo 0 and 1, nothing NaN") {
    const std::vector<glm::vec3> albedos = {glm::vec3(0.0f), glm::vec3(1.0f)};
    for (const glm::vec3& albedo : albedos) {
        CAPTURE(albedo.r);
        const VolumeMedium free = medium(glm::vec3(0.0f), albedo);
        const VolumeResult r0 = compositeVolumes({boundary(1, 0, free, true), boundary(2, 0, free, false)}, MediumSet(),
                                                 10.0, kBackground, kLs);
        CHECK(r0.color == kBackground);
        const VolumeMedium dense = medium(glm::vec3(1e6f), albedo);
        for (double thickness : {1.0, 1e-3, 0.0}) {
            CAPTURE(thickness);
            const VolumeResult r = compositeVolumes(
                {boundary(1, 0, dense, true), boundary(1 + thickness, 0, dense, false)}, MediumSet(), 10.0, kBackground, kLs);
            for (int k = 0; k < 3; ++k) {
                CHECK(std::isfinite(r.color[k]));
                if (thickness == 0.0) {
                    CHECK(r.color[k] == kBackground[k]);
                } else {
                    CHECK(r.transmittance[k] == 0.0f);
                    CHECK(r.color[k] == doctest::Approx(albedo[k] * kLs).epsilon(1e-6));
                }
            }
        }
    }
    // tau * d of 1e-9: the scattered radiance is sigma L^s d to first order, not lost to round-off.
    const VolumeMedium thin = medium(glm::vec3(1e-9f), glm::vec3(1.0f));
    const VolumeResult r = compositeVolumes({boundary(1, 0, thin, true), boundary(2, 0, thin, false)}, MediumSet(), 10.0,
                                            glm::vec3(0.0f), kLs);
    CHECK(r.color.r == doctest::Approx(1e-9 * kLs).epsilon(1e-6));
}

TEST_CASE("more volumes overlapping than the limit are counted, not silently merged") {
    std::vector<VolumeMedium> media(kMaxNestedVolumes + 2, medium(glm::vec3(0.1f), glm::vec3(0.5f)));
    std::vector<VolumeFragment> list;
    for (int i = 0; i < int(media.size()); ++i) list.push_back(boundary(1.0 + i, i, media[std::size_t(i)], true));
    const VolumeResult r = compositeVolumes(list, MediumSet(), 20.0, kBackground, kLs);
    CHECK(r.nestingOverflow == 2);
}

TEST_CASE("L^s is L^a plus the Rayleigh phase function of the angle to the light") {
    const glm::vec3 light(0.0f, 0.0f, 1.0f);
    const float along = inscatteredRadiance(light, glm::vec3(0.0f, 0.0f, -2.0f));
    const float across = inscatteredRadiance(light, glm::vec3(1.0f, 0.0f, 0.0f));
    const double irradiance = 3.14159265358979 * (1.0 - 0.3);
    CHECK(along == doctest::Approx(0.3 + irradiance * 3.0 / (16.0 * 3.14159265358979) * 2.0).epsilon(1e-6));
    CHECK(across == doctest::Approx(0.3 + irradiance * 3.0 / (16.0 * 3.14159265358979)).epsilon(1e-6));
}
