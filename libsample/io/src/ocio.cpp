// OpenColorIO: the config, colour-space names and conversions (OCIO 2.1 API,
// https://opencolorio.readthedocs.io/en/latest/api/config.html).
#include "io_internal.h"

#include <OpenColorIO/OpenColorIO.h>
#include <dlfcn.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace OCIO = OCIO_NAMESPACE;

struct io_colour {
    OCIO::ConstConfigRcPtr config;
    std::string path; // for messages
};

static bool file_exists(const std::string &p)
{
    struct stat st;
    return stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// Where the shipped config lies relative to an installed object: the
// install puts it in <prefix>/share/libsample/ocio/, and the objects that
// hold this code sit one to three directories below <prefix> (bin/,
// lib/, lib/<multiarch>/, libexec/libsample/). So the directory holding the
// object and its parents up to three levels are searched for
// share/libsample/ocio/config.ocio: an installed tree can be moved, and no
// absolute install path is baked in.
static const int shipped_config_depth = 3;

static std::string directory_of(const std::string &path)
{
    size_t slash = path.rfind('/');
    if (slash == std::string::npos) return std::string();
    return slash == 0 ? std::string("/") : path.substr(0, slash);
}

static std::string shipped_config_below(std::string dir)
{
    for (int up = 0; up <= shipped_config_depth && !dir.empty(); ++up) {
        std::string p = (dir == "/" ? std::string() : dir) + "/share/libsample/ocio/config.ocio";
        if (file_exists(p)) return p;
        if (dir == "/") break;
        dir = directory_of(dir);
    }
    return std::string();
}

// The object's own path, symbolic links resolved. dladdr names a shared
// library by the path it was loaded from, but for code linked into the
// program itself glibc reports argv[0], which for a program run from $PATH
// is a bare name: /proc/self/exe (proc(5)) is the program's real path.
static std::string real_path(const char *p)
{
    char *r = p ? realpath(p, nullptr) : nullptr;
    std::string s = r ? r : "";
    std::free(r);
    return s;
}

// The shipped config: below the object holding this function (the shared
// libsample_io, or the program it is linked into), then below the running
// program, then in the source tree this build came from (build-tree use).
static std::string shipped_config()
{
    Dl_info info;
    std::string found;
    if (dladdr(reinterpret_cast<void *>(&shipped_config), &info) && info.dli_fname &&
        std::strchr(info.dli_fname, '/'))
        found = shipped_config_below(directory_of(real_path(info.dli_fname)));
    if (found.empty()) found = shipped_config_below(directory_of(real_path("/proc/self/exe")));
    return found.empty() ? std::string(SAMPLE_IO_OCIO_SOURCE) : found;
}

extern "C" sample_status io_colour_open(const char *path, io_colour **out, sample_error *err)
{
    std::string p;
    *out = nullptr;
    if (path && *path) {
        p = path;
    } else {
        const char *env = std::getenv("OCIO");
        p = (env && *env) ? env : shipped_config();
    }
    // A FIFO or device named as the config would block or never end
    // (io_regular.c); it is a config problem, so SAMPLE_E_COLOR.
    if (sample_io_check_regular_file(p.c_str(), "OCIO config", err) != SAMPLE_OK) {
        if (err) err->status = SAMPLE_E_COLOR;
        return SAMPLE_E_COLOR;
    }
    try {
        auto *c = new io_colour;
        try {
            c->config = OCIO::Config::CreateFromFile(p.c_str());
            c->path = p;
        } catch (...) {
            delete c;
            throw;
        }
        *out = c;
        return SAMPLE_OK;
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_COLOR, "cannot load OCIO config '%s': %s", p.c_str(), e.what());
    }
}

extern "C" void io_colour_close(io_colour *c) { delete c; }

extern "C" int io_colour_known(const io_colour *c, const char *name)
{
    try {
        return name && *name && c->config->getColorSpace(name) != nullptr;
    } catch (...) {
        return 0;
    }
}

extern "C" sample_status io_colour_require(const io_colour *c, const char *name, sample_error *err)
{
    if (io_colour_known(c, name)) return SAMPLE_OK;
    // The names a user can give instead, as many as the message holds
    // (sample_error's 256 bytes), then how many more there are.
    std::string list;
    int n = 0, total = 0;
    try {
        total = c->config->getNumColorSpaces();
        for (; n < total; ++n) {
            std::string next = std::string(n ? ", " : "") + c->config->getColorSpaceNameByIndex(n);
            if (list.size() + next.size() > 110) break;
            list += next;
        }
    } catch (...) {
        // A config that cannot list its spaces still gets the first part.
    }
    std::string more = n < total ? ", and " + std::to_string(total - n) + " more" : std::string();
    return sample_error_set(err, SAMPLE_E_COLOR, "unknown colour space '%s'; the OCIO config '%s' has %s%s",
                            name ? name : "", c->path.c_str(), list.c_str(), more.c_str());
}

// ACES2065-1's primaries to CIE XYZ (SMPTE ST 2065-1:2012, the AP0 NPM).
static const double ap0_to_xyz[3][3] = {{0.9525523959, 0.0, 0.0000936786},
                                        {0.3439664498, 0.7281660966, -0.0721325464},
                                        {0.0, 0.0, 1.0088251844}};

// Chromaticities a file can be labelled with (CIE xy of red, green, blue,
// white): the two ACES primary sets, which share the ACES white (SMPTE ST
// 2065-1 for AP0, Academy S-2014-004 for ACEScg's AP1).
static const struct {
    const char *what;
    float xy[8];
} known_primaries[] = {
    {"AP0", {0.7347f, 0.2653f, 0.0000f, 1.0000f, 0.0001f, -0.0770f, 0.32168f, 0.33767f}},
    {"AP1", {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f}},
};

// The chromaticities of linear space `name`, where the config ties it to
// ACES2065-1 (the aces_interchange role, OCIO 2.1): the images of pure red,
// green, blue and white in AP0, then in XYZ. Only the ACES primary sets are
// answered: a space with another white (Rec.709's D65) reaches AP0 through
// a chromatic adaptation baked into its matrix, and its own chromaticities
// cannot be read back from the adapted ones; its file then carries none,
// which OpenEXR reads as Rec.709.
static bool chromaticities(const io_colour *c, const char *name, float xy[8])
{
    auto aces = c->config->getColorSpace(OCIO::ROLE_INTERCHANGE_SCENE);
    auto cs = c->config->getColorSpace(name);
    if (!aces || !cs || cs->isData()) return false;
    auto cpu = c->config->getProcessor(name, OCIO::ROLE_INTERCHANGE_SCENE)->getDefaultCPUProcessor();
    float rgb[5][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {0.18f, 0.18f, 0.18f}};
    double found[8];
    for (auto &p : rgb) cpu->applyRGB(p);
    for (int k = 0; k < 3; ++k) // linear: mid grey is 0.18 white
        if (std::fabs(rgb[4][k] - 0.18f * rgb[3][k]) > 1e-4f * (1.0f + std::fabs(rgb[3][k]))) return false;
    for (int p = 0; p < 4; ++p) {
        double xyz[3], sum = 0;
        for (int r = 0; r < 3; ++r) {
            xyz[r] = ap0_to_xyz[r][0] * rgb[p][0] + ap0_to_xyz[r][1] * rgb[p][1] + ap0_to_xyz[r][2] * rgb[p][2];
            sum += xyz[r];
        }
        if (!(std::fabs(sum) > 1e-9)) return false;
        found[2 * p] = xyz[0] / sum;
        found[2 * p + 1] = xyz[1] / sum;
    }
    for (const auto &k : known_primaries) {
        bool same = true;
        for (int i = 0; i < 8; ++i) same = same && std::fabs(found[i] - k.xy[i]) < 2e-3;
        if (same) {
            std::memcpy(xy, k.xy, sizeof k.xy);
            return true;
        }
    }
    return false;
}

extern "C" void io_colour_label_get(const io_colour *c, const char *name, io_colour_label *out)
{
    std::memset(out, 0, sizeof *out);
    try {
        auto cs = c->config->getColorSpace(name);
        std::snprintf(out->name, sizeof out->name, "%s", cs ? cs->getName() : name);
        out->has_chromaticities = chromaticities(c, name, out->chromaticities);
    } catch (...) {
        std::snprintf(out->name, sizeof out->name, "%s", name);
        out->has_chromaticities = 0;
    }
}

static OCIO::ConstCPUProcessorRcPtr processor(const io_colour *c, const char *name, int to_linear)
{
    const char *lin = OCIO::ROLE_SCENE_LINEAR;
    auto proc = to_linear ? c->config->getProcessor(name, lin) : c->config->getProcessor(lin, name);
    // LOSSLESS leaves out OPTIMIZATION_FAST_LOG_EXP_POW, whose approximate pow
    // would cost the exactness an 8-bit round trip needs (OpenColorTypes.h).
    return proc->getOptimizedCPUProcessor(OCIO::OPTIMIZATION_LOSSLESS);
}

extern "C" int io_colour_is_linear(const io_colour *c, const char *name)
{
    try {
        auto cs = c->config->getColorSpace(name);
        if (!cs) return 0;
        return cs->isData() || c->config->getProcessor(name, OCIO::ROLE_SCENE_LINEAR)->isNoOp();
    } catch (...) {
        return 0;
    }
}

extern "C" int io_colour_is_srgb(const io_colour *c, const char *name)
{
    try {
        auto cs = c->config->getColorSpace(name);
        if (!cs || cs->isData()) return 0;
        auto cpu = processor(c, name, 1);
        // Three different codes per pixel so that a matrix (other primaries)
        // shows as well as a different curve.
        std::vector<float> rgb(256 * 3);
        for (int k = 0; k < 256; ++k) {
            rgb[3 * k + 0] = (float)k / 255.0f;
            rgb[3 * k + 1] = (float)(255 - k) / 255.0f;
            rgb[3 * k + 2] = (float)((k * 7) % 256) / 255.0f;
        }
        std::vector<float> ref(rgb);
        OCIO::PackedImageDesc desc(rgb.data(), 256, 1, 3);
        cpu->apply(desc);
        for (size_t k = 0; k < rgb.size(); ++k) {
            double want = sample_srgb_to_linear(ref[k]);
            // OCIO derives the linear segment's slope for continuity
            // (12.923 rather than 12.92), a relative difference of 2e-4 at
            // most, far below 8-bit resolution.
            if (!(std::fabs(rgb[k] - want) <= 1e-6 + 5e-4 * want)) return 0;
        }
        return 1;
    } catch (...) {
        return 0;
    }
}

extern "C" sample_status io_colour_apply(const io_colour *c, const char *name, int to_linear, float *px,
                                         size_t n, int nchan, sample_error *err)
{
    try {
        auto cpu = processor(c, name, to_linear);
        if (cpu->isNoOp()) return SAMPLE_OK;
        // Convert in chunks through a packed RGB buffer: OCIO wants at least
        // RGB, and alpha must not be touched.
        const size_t chunk = 4096;
        std::vector<float> rgb(chunk * 3);
        for (size_t i0 = 0; i0 < n; i0 += chunk) {
            size_t m = n - i0 < chunk ? n - i0 : chunk;
            for (size_t i = 0; i < m; ++i) {
                const float *p = px + (i0 + i) * (size_t)nchan;
                for (int k = 0; k < 3; ++k) rgb[3 * i + k] = p[nchan >= 3 ? k : 0];
            }
            OCIO::PackedImageDesc desc(rgb.data(), (long)m, 1, 3);
            cpu->apply(desc);
            for (size_t i = 0; i < m; ++i) {
                float *p = px + (i0 + i) * (size_t)nchan;
                for (int k = 0; k < (nchan >= 3 ? 3 : 1); ++k) p[k] = rgb[3 * i + k];
            }
        }
        return SAMPLE_OK;
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_COLOR, "colour conversion %s '%s': %s", to_linear ? "from" : "to", name,
                       e.what());
    } catch (...) {
        return sample_error_set(err, SAMPLE_E_COLOR, "colour conversion with '%s' failed", name);
    }
}
