// OpenColorIO: the config, colour-space names and conversions (OCIO 2.1 API,
// https://opencolorio.readthedocs.io/en/latest/api/config.html).
#include "io_internal.h"

#include <OpenColorIO/OpenColorIO.h>
#include <dlfcn.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace OCIO = OCIO_NAMESPACE;

struct io_colour {
    OCIO::ConstConfigRcPtr config;
};

static bool file_exists(const std::string &p)
{
    struct stat st;
    return stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// The shipped config: first beside the installed binary or library (the
// object holding this function, found with dladdr, so an installed tree can
// be moved), then in the source tree this build came from.
static std::string shipped_config()
{
    Dl_info info;
    if (dladdr(reinterpret_cast<void *>(&shipped_config), &info) && info.dli_fname) {
        std::string dir(info.dli_fname);
        size_t slash = dir.rfind('/');
        dir = slash == std::string::npos ? std::string(".") : dir.substr(0, slash);
        for (const char *rel : {SAMPLE_IO_OCIO_FROM_LIBDIR, "../share/libsample/ocio/config.ocio"}) {
            std::string p = dir + "/" + rel;
            if (file_exists(p)) return p;
        }
    }
    return SAMPLE_IO_OCIO_SOURCE;
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
