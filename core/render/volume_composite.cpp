#include "render/volume_composite.hpp"

#include "render/shading.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace strata {

VolumeMedium mediumOf(const Material& material) { return {material.tau, material.tau * material.albedo}; }

float inscatteredRadiance(const glm::vec3& lightDirection, const glm::vec3& viewDirection) {
    const float ambient = kAmbient;
    const float irradiance = glm::pi<float>() * (1.0f - kAmbient);
    const float lv = glm::length(lightDirection) * glm::length(viewDirection);
    const float cosTheta = lv > 0.0f ? glm::dot(lightDirection, viewDirection) / lv : 0.0f;
    return ambient + irradiance * 3.0f / (16.0f * glm::pi<float>()) * (1.0f + cosTheta * cosTheta);
}

double segmentIntegral(double tau, double length) {
    if (!(tau > 0.0)) return length;
    return -std::expm1(-tau * length) / tau;
}

bool MediumSet::cross(int object, const VolumeMedium& medium, int step) {
    auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.object == object; });
    if (it == entries_.end()) {
        if (int(entries_.size()) >= kMaxNestedVolumes) return false;
        entries_.push_back({object, step, medium});
        return true;
    }
    it->count += step;
    if (it->count == 0) entries_.erase(it);
    return true;
}

VolumeMedium MediumSet::sum() const {
    VolumeMedium total;
    for (const Entry& e : entries_) {
        if (e.count <= 0) continue;
        total.tau += e.medium.tau;
        total.scatter += e.medium.scatter;
    }
    return total;
}

VolumeResult compositeVolumes(const std::vector<VolumeFragment>& fragments, const MediumSet& eyeInside,
                              double endDistance, const glm::vec3& background, float inscattered) {
    VolumeResult out;
    MediumSet inside = eyeInside;
    glm::dvec3 color(0.0), transmittance(1.0);
    double reached = 0.0;  // the farthest distance the walk has covered
    auto advance = [&](double to) {
        const double length = std::max(0.0, to - reached);
        reached = std::max(reached, to);
        if (length <= 0.0) return;
        const VolumeMedium m = inside.sum();
        for (int k = 0; k < 3; ++k) {
            const double tau = m.tau[k];
            color[k] += transmittance[k] * double(inscattered) * double(m.scatter[k]) * segmentIntegral(tau, length);
            transmittance[k] *= std::exp(-tau * length);
        }
    };
    for (const VolumeFragment& f : fragments) {
        advance(f.distance);
        if (f.medium) {
            if (!inside.cross(f.object, *f.medium, f.entry ? 1 : -1)) ++out.nestingOverflow;
            continue;
        }
        color += transmittance * double(f.alpha) * glm::dvec3(f.color);
        transmittance *= f.coloredFilter ? glm::dvec3(f.transmittance) : glm::dvec3(1.0 - double(f.alpha));
    }
    advance(endDistance);
    out.color = glm::vec3(color + transmittance * glm::dvec3(background));
    out.transmittance = glm::vec3(transmittance);
    return out;
}

}  // namespace strata
