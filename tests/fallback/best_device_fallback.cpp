// openBestDevice with some backends hidden by the environment (CTest's ENVIRONMENT property:
// VK_ICD_FILENAMES=/nonexistent hides the Vulkan driver, __EGL_VENDOR_LIBRARY_FILENAMES=
// /nonexistent every EGL vendor, LD_LIBRARY_PATH to osmesa_stub's libOSMesa.so.8, or to a file of
// that name that is not a library, OSMesa).
// Usage: sfx_best_device_fallback <hidden>... where each hidden backend is a name of
// toString(BackendConfig). Checks that
//   - each hidden backend really fails to open, with BackendUnavailable;
//   - openBestDevice still succeeds, on a backend that is not hidden;
//   - every other compiled backend is in `rejected`, the hidden ones with the reason they
//     failed to open;
//   - when every compiled backend is hidden: openBestDevice is BackendUnavailable (the null
//     backend is never chosen: it is not in compiledBackends) and its message names each
//     backend with the reason it did not open.
// Exit 0 pass, 1 fail, 77 when no backend is left to fall back to on this machine.
#include <cstdio>
#include <set>
#include <string>

#include "sfx/backends.hpp"

using namespace sfx;

namespace {

int failures = 0;
void check(bool ok, const std::string& what) {
    std::printf("%s: %s\n", ok ? "ok" : "FAIL", what.c_str());
    if (!ok) ++failures;
}

}  // namespace

int main(int argc, char** argv) {
    std::set<std::string> hidden;
    for (int i = 1; i < argc; ++i) hidden.insert(argv[i]);
    const std::vector<BackendConfig> compiled = compiledBackends();
    std::set<std::string> names;
    for (const BackendConfig& c : compiled) names.insert(toString(c));
    for (const std::string& h : hidden)
        if (!names.count(h)) {
            std::printf("skip: backend '%s' is not in this build\n", h.c_str());
            return 77;
        }

    if (hidden.size() == compiled.size()) {
        for (const BackendConfig& c : compiled) {
            Result<std::unique_ptr<Device>> d = openDevice(c);
            check(!d && d.status().code() == StatusCode::BackendUnavailable,
                  "the environment hides " + toString(c) + " (" + (d ? std::string("it opened") : d.status().toString()) + ")");
        }
        Result<DeviceSelection> none = openBestDevice();
        check(!none && none.status().code() == StatusCode::BackendUnavailable,
              "openBestDevice with every backend hidden: " + (none ? "chose " + toString(none->config) : none.status().toString()));
        if (none) return 1;
        const std::string& message = none.status().message();
        check(message.rfind("no backend could be opened:", 0) == 0, "the message says no backend could be opened");
        for (const BackendConfig& c : compiled) {
            // One line per backend: "\n  <name>: BackendUnavailable: <reason>".
            const std::string line = "\n  " + toString(c) + ": BackendUnavailable: ";
            const size_t at = message.find(line);
            const size_t reasonEnd = at == std::string::npos ? at : message.find('\n', at + line.size());
            const size_t reasonLength = at == std::string::npos ? 0
                                                                : (reasonEnd == std::string::npos ? message.size() : reasonEnd) - (at + line.size());
            check(reasonLength > 0, "the message gives why " + toString(c) + " did not open");
        }
        return failures ? 1 : 0;
    }

    bool anyLeft = false;
    for (const BackendConfig& c : compiled) {
        const std::string name = toString(c);
        Result<std::unique_ptr<Device>> d = openDevice(c);
        if (hidden.count(name))
            check(!d && d.status().code() == StatusCode::BackendUnavailable,
                  "the environment hides " + name + " (" + (d ? std::string("it opened") : d.status().toString()) + ")");
        else
            anyLeft = anyLeft || d.isOk();
    }
    if (!anyLeft) {
        std::printf("skip: no backend besides the hidden ones opens on this machine\n");
        return failures ? 1 : 77;
    }

    Result<DeviceSelection> best = openBestDevice();
    check(best.isOk(), "openBestDevice falls back: " + (best ? best->reason : best.status().toString()));
    if (!best) return 1;
    const std::string chosen = toString(best->config);
    std::printf("chose %s\n", chosen.c_str());
    for (const std::string& r : best->rejected) std::printf("rejected %s\n", r.c_str());
    check(!hidden.count(chosen), "the chosen backend " + chosen + " is not a hidden one");
    check(best->rejected.size() + 1 == compiled.size(), "every other compiled backend is in rejected");
    for (const std::string& h : hidden) {
        bool named = false;
        for (const std::string& r : best->rejected) named = named || (r.rfind(h + ": ", 0) == 0 && r.find("BackendUnavailable") != std::string::npos);
        check(named, "rejected gives why " + h + " did not open");
    }
    return failures ? 1 : 0;
}
