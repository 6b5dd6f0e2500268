// The device's defaults: which renderer counts as software, what a hardware one changes, and that
// the user's assignments still win over them.
#include "gl/context.hpp"
#include "oit/device_defaults.hpp"
#include "oit/technique.hpp"

#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

using namespace strata;

namespace {

const gl::DeviceInfo kLlvmpipe{"Mesa", "llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 22.3.6"};
const gl::DeviceInfo kSoftpipe{"Mesa", "softpipe", "4.5 (Core Profile) Mesa 22.3.6"};
const gl::DeviceInfo kH200{"NVIDIA Corporation", "NVIDIA H200/PCIe/SSE2", "4.5.0 NVIDIA 580.159.04"};

double valueOf(const SettingsById& s, const std::string& id, const std::string& name) {
    const auto& ds = findTechnique(id)->settings;
    for (std::size_t i = 0; i < ds.size(); ++i)
        if (ds[i].name == name) return s.at(id).at(i);
    throw std::logic_error(id + " has no " + name);
}

}  // namespace

TEST_CASE("device defaults: Mesa's software rasterizers are software, a GPU is not") {
    CHECK(kLlvmpipe.software());
    CHECK(kSoftpipe.software());
    CHECK_FALSE(kH200.software());
    CHECK_FALSE(gl::DeviceInfo{"AMD", "AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6)", "4.6"}.software());
}

TEST_CASE("device defaults: dual finds its range by atomics on a hardware renderer only") {
    const std::vector<std::string> ids = {"f2b", "dual", "abuffer"};
    CHECK(deviceDefaultSettings(ids, kLlvmpipe).empty());  // none of these has a software default
    const auto hardware = deviceDefaultSettings(ids, kH200);
    REQUIRE(hardware.size() == 1);
    CHECK(hardware[0].text == "dual.atomic_range=1");
    CHECK(hardware[0].origin.find("NVIDIA H200") != std::string::npos);  // an error names the device

    CHECK(valueOf(resolveSettingsForDevice(ids, {}, kLlvmpipe), "dual", "atomic_range") == 0);
    CHECK(valueOf(resolveSettingsForDevice(ids, {}, kH200), "dual", "atomic_range") == 1);
    // Nothing else moves.
    const SettingsById plain = resolveSettings(ids, {});
    const SettingsById gpu = resolveSettingsForDevice(ids, {}, kH200);
    CHECK(gpu.at("f2b") == plain.at("f2b"));
    CHECK(gpu.at("abuffer") == plain.at("abuffer"));
    CHECK(valueOf(gpu, "dual", "precision") == valueOf(plain, "dual", "precision"));
}

TEST_CASE("device defaults: --set and presets override them, and techniques without the setting are untouched") {
    const std::vector<std::string> ids = {"dual"};
    CHECK(valueOf(resolveSettingsForDevice(ids, {{"dual.atomic_range=0", "--set"}}, kH200), "dual", "atomic_range") == 0);
    CHECK(valueOf(resolveSettingsForDevice(ids, {{"atomic_range=false", "--set"}}, kH200), "dual", "atomic_range") == 0);
    CHECK(valueOf(resolveSettingsForDevice(ids, {{"atomic_range=1", "--set"}}, kLlvmpipe), "dual", "atomic_range") == 1);
    // Without dual among the ids the default is left out, so resolving cannot fail on it.
    CHECK(deviceDefaultSettings({"f2b", "abuffer"}, kH200).empty());
    CHECK_NOTHROW(resolveSettingsForDevice({"f2b"}, {}, kH200));
}

TEST_CASE("device defaults: wboit accumulates in 32-bit floats on a software renderer only") {
    const std::vector<std::string> ids = {"wboit", "dual"};
    const auto software = deviceDefaultSettings(ids, kLlvmpipe);
    REQUIRE(software.size() == 1);
    CHECK(software[0].text == "wboit.precision=32");
    CHECK(software[0].origin.find("llvmpipe") != std::string::npos);
    CHECK(valueOf(resolveSettingsForDevice(ids, {}, kLlvmpipe), "wboit", "precision") == 32);
    CHECK(valueOf(resolveSettingsForDevice(ids, {}, kH200), "wboit", "precision") == 16);
    CHECK(valueOf(resolveSettings(ids, {}), "wboit", "precision") == 16);  // the struct's default
    // The user's choice still wins, and dual keeps its own default on llvmpipe.
    CHECK(valueOf(resolveSettingsForDevice(ids, {{"wboit.precision=16", "--set"}}, kLlvmpipe), "wboit", "precision") == 16);
    CHECK(valueOf(resolveSettingsForDevice(ids, {}, kLlvmpipe), "dual", "atomic_range") == 0);
}
