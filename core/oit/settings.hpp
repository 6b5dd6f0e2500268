#pragma once
// Technique settings. Each technique keeps its knobs in a plain struct and describes each field
// once: name, type, range, default, help and what a change forces. `--set`, JSON presets, the
// panel, `strata modes --settings` and the bench report all read that one description, so a
// setting cannot be documented in one place and validated differently in another.
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace strata {

enum class SettingType { Integer, Real, Flag };

// What the next frame must do after the value changed; shown beside the setting so a user knows
// a drag of the slider will reallocate GPU memory or rebuild programs.
enum class SettingChange { Nothing, Reallocate, Recompile };

struct SettingDescription {
    std::string name;
    SettingType type = SettingType::Integer;
    double min = 0;
    double max = 1;
    std::vector<double> allowed;  // when non-empty, the only values accepted (precision: 16 or 32)
    double defaultValue = 0;
    SettingChange change = SettingChange::Nothing;
    std::string help;
};

// One technique's setting values in the order of its descriptions. Integers and flags are held
// exactly: every integer setting's range lies within +-2^53.
using SettingValues = std::vector<double>;

const char* toString(SettingType type);
const char* toString(SettingChange change);

// Parses `text` as a value of `d`: an integer for integers (no fraction, no exponent), a finite
// number for reals, 0/1/true/false/on/off for flags; checks the range and the allowed values.
// Throws std::invalid_argument with a one-line reason that names the setting.
double parseSettingValue(const SettingDescription& d, std::string_view text);
// Checks a value already held as a number (a JSON preset, the panel) the same way.
void checkSettingValue(const SettingDescription& d, double value);
// The value as the command line would write it: "16", "0.25", "true".
std::string formatSettingValue(const SettingDescription& d, double value);
// "integer in [1, 64]", "16 or 32", "real in [0, 1e+06]", "flag".
std::string describeRange(const SettingDescription& d);

// Binds the fields of the settings struct S to their descriptions. A technique defines one
// static schema for its struct; the defaults are the struct's member initializers.
template <class S>
class SettingsSchema {
public:
    // Reads and writes one field as a double; made from a member pointer of the field's own
    // type (see memberAccess), so an int is never read through a double.
    struct Field {
        SettingDescription description;
        std::function<double(const S&)> get;
        std::function<void(S&, double)> set;
    };

    SettingsSchema(std::initializer_list<Field> fields) : SettingsSchema(std::vector<Field>(fields)) {}
    // A technique whose struct extends another's fields (dual's peeling settings and its own).
    explicit SettingsSchema(std::vector<Field> fields) : fields_(std::move(fields)) {
        const S defaults{};
        for (auto& f : fields_) {
            // A field built without memberAccess would fail only when first written.
            if (!f.get || !f.set) throw std::logic_error("setting " + f.description.name + " has no accessors");
            f.description.defaultValue = f.get(defaults);
        }
    }

    std::vector<SettingDescription> descriptions() const {
        std::vector<SettingDescription> out;
        for (const auto& f : fields_) out.push_back(f.description);
        return out;
    }
    SettingValues read(const S& s) const {
        SettingValues out;
        for (const auto& f : fields_) out.push_back(f.get(s));
        return out;
    }
    // Values must come from resolveSettings or the panel (already checked); a missing tail keeps
    // the defaults.
    S write(const SettingValues& values) const {
        S s{};
        for (std::size_t i = 0; i < fields_.size() && i < values.size(); ++i) fields_[i].set(s, values[i]);
        return s;
    }

private:
    std::vector<Field> fields_;
};

template <class S, class T>
typename SettingsSchema<S>::Field memberAccess(SettingDescription description, T S::*member) {
    return {std::move(description), [member](const S& s) { return double(s.*member); },
            [member](S& s, double v) {
                if constexpr (std::is_same_v<T, bool>) s.*member = v != 0;
                else s.*member = T(v);
            }};
}

template <class S>
typename SettingsSchema<S>::Field integerSetting(int S::*member, std::string name, int min, int max,
                                                 SettingChange change, std::string help) {
    return memberAccess<S>({std::move(name), SettingType::Integer, double(min), double(max), {}, 0, change, std::move(help)},
                           member);
}

template <class S>
typename SettingsSchema<S>::Field realSetting(double S::*member, std::string name, double min, double max,
                                              SettingChange change, std::string help) {
    return memberAccess<S>({std::move(name), SettingType::Real, min, max, {}, 0, change, std::move(help)}, member);
}

template <class S>
typename SettingsSchema<S>::Field flagSetting(bool S::*member, std::string name, SettingChange change, std::string help) {
    return memberAccess<S>({std::move(name), SettingType::Flag, 0, 1, {}, 0, change, std::move(help)}, member);
}

// Bits per channel of a technique's own float targets: 16 (half float) or 32. Reallocates them.
template <class S>
typename SettingsSchema<S>::Field precisionSetting(int S::*member, std::string what) {
    return memberAccess<S>({"precision", SettingType::Integer, 16, 32, {16, 32}, 0, SettingChange::Reallocate,
                            "bits per channel of the " + what + ": 16 (half float) or 32 (float)"},
                           member);
}

// For techniques without knobs.
struct NoSettings {
    static const SettingsSchema<NoSettings>& schema() {
        static const SettingsSchema<NoSettings> s{};
        return s;
    }
};

}  // namespace strata
