// oiio_replay: times the queries that `texsample bench --save DIR` recorded
// through OpenImageIO's TextureSystem, on its own, and sets its numbers
// beside bench's (doc/benchmarks.md, "Re-timing the same queries
// independently").
//
// It is deliberately separate from bench: it links OpenImageIO and nothing
// of ours (not the shim in tools/oiio, not libsample), reads only the files
// in DIR, and builds every TextureOpt from the manifest's words. If bench's
// shim set an option differently from what the manifest says, or timed
// something else than the queries it saved, the two ratios (or --dump's
// values, tests/bench_replay.c) disagree.
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <utility>
#include <vector>

using namespace OIIO;

namespace {

enum { EXIT_OK = 0, EXIT_RUNTIME = 1, EXIT_USAGE = 2 };

const char help[] =
    "usage: oiio_replay DIR [--runs N] [--dump OUTDIR]\n\n"
    "Re-times, through OpenImageIO's TextureSystem, the queries that\n"
    "'texsample bench --save DIR' recorded, with the TextureOpt settings\n"
    "DIR/manifest.json gives for each filter, and prints samples per second\n"
    "per set x format x filter. Where the manifest holds bench's own 1-thread\n"
    "numbers it prints bench's ratio (ours / OIIO) beside the ratio computed\n"
    "from this program's OIIO timing, and how far apart they are.\n\n"
    "It shares no code with bench: a private TextureSystem whose cache holds\n"
    "every texture file (no eviction), 1 thread, one texture() call per query\n"
    "with the derivatives as recorded, one untimed warm-up pass, then the\n"
    "median of N timed passes. Filters without an OIIO twin are skipped.\n\n"
    "Options:\n"
    "  DIR             a directory written by bench --save (or its manifest.json)\n"
    "  --runs N        timed passes per measurement (default 5)\n"
    "  --dump OUTDIR   also write each lookup's results, OUTDIR/SET_FORMAT_FILTER.rgba:\n"
    "                  nchannels little-endian float32 per query, in query order\n"
    "                  (OUTDIR is created if missing)\n"
    "  -h, --help      this text\n\n"
    "Exit codes: 0 success, 1 runtime error (unreadable, garbled or truncated\n"
    "input, a failed lookup), 2 usage error.\n";

struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---- A small JSON reader, enough for our own manifest -----------------------
//
// Bounded on every axis a garbled file could exploit: the text is read whole
// up to a size cap, nesting is capped (no stack overflow on "[[[[..."), and
// every loop advances through the text.

struct Json {
    enum Type { Null, Bool, Number, String, Array, Object } type = Null;
    bool boolean = false;
    double number = 0.0;
    std::string str;
    std::vector<Json> items;                           // Array
    std::vector<std::pair<std::string, Json>> members; // Object, in file order

    const Json *get(const char *key) const
    {
        for (const auto &m : members)
            if (m.first == key) return &m.second;
        return nullptr;
    }
};

class Parser {
public:
    Parser(const std::string &text, const std::string &name) : s_(text), name_(name) {}

    Json parse()
    {
        Json v = value(0);
        space();
        if (p_ != s_.size()) fail("unexpected text after the JSON value");
        return v;
    }

private:
    static constexpr int max_depth = 64;
    const std::string &s_;
    const std::string &name_;
    size_t p_ = 0;

    [[noreturn]] void fail(const std::string &what) const
    {
        throw Failure(name_ + ": not valid JSON at byte " + std::to_string(p_) + ": " + what);
    }
    void space()
    {
        while (p_ < s_.size() && (s_[p_] == ' ' || s_[p_] == '\t' || s_[p_] == '\n' || s_[p_] == '\r'))
            ++p_;
    }
    bool eat(char c)
    {
        space();
        if (p_ < s_.size() && s_[p_] == c) {
            ++p_;
            return true;
        }
        return false;
    }
    bool word(const char *w)
    {
        size_t n = std::strlen(w);
        if (s_.compare(p_, n, w) != 0) return false;
        p_ += n;
        return true;
    }

    Json value(int depth)
    {
        if (depth > max_depth) fail("nested too deeply");
        space();
        if (p_ >= s_.size()) fail("unexpected end of file");
        Json v;
        char c = s_[p_];
        if (c == '{') {
            ++p_;
            v.type = Json::Object;
            if (eat('}')) return v;
            do {
                space();
                if (p_ >= s_.size() || s_[p_] != '"') fail("expected a member name");
                std::string key = string();
                if (!eat(':')) fail("expected ':'");
                v.members.emplace_back(std::move(key), value(depth + 1));
            } while (eat(','));
            if (!eat('}')) fail("expected ',' or '}'");
        } else if (c == '[') {
            ++p_;
            v.type = Json::Array;
            if (eat(']')) return v;
            do v.items.push_back(value(depth + 1));
            while (eat(','));
            if (!eat(']')) fail("expected ',' or ']'");
        } else if (c == '"') {
            v.type = Json::String;
            v.str = string();
        } else if (word("true")) {
            v.type = Json::Bool;
            v.boolean = true;
        } else if (word("false")) {
            v.type = Json::Bool;
        } else if (word("null")) {
            v.type = Json::Null;
        } else {
            v.type = Json::Number;
            v.number = number();
        }
        return v;
    }

    unsigned hex4()
    {
        unsigned u = 0;
        for (int k = 0; k < 4; ++k, ++p_) {
            if (p_ >= s_.size() || !std::isxdigit((unsigned char)s_[p_])) fail("bad \\u escape");
            char h = s_[p_];
            u = u * 16 + (unsigned)(h <= '9' ? h - '0' : (h | 0x20) - 'a' + 10);
        }
        return u;
    }

    static void utf8(std::string &out, unsigned cp)
    {
        if (cp < 0x80) {
            out += (char)cp;
        } else if (cp < 0x800) {
            out += (char)(0xC0 | (cp >> 6));
            out += (char)(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += (char)(0xE0 | (cp >> 12));
            out += (char)(0x80 | ((cp >> 6) & 0x3F));
            out += (char)(0x80 | (cp & 0x3F));
        } else {
            out += (char)(0xF0 | (cp >> 18));
            out += (char)(0x80 | ((cp >> 12) & 0x3F));
            out += (char)(0x80 | ((cp >> 6) & 0x3F));
            out += (char)(0x80 | (cp & 0x3F));
        }
    }

    std::string string()
    {
        std::string out;
        ++p_; // the opening quote
        for (;;) {
            if (p_ >= s_.size()) fail("unterminated string");
            unsigned char c = (unsigned char)s_[p_++];
            if (c == '"') return out;
            if (c < 0x20) fail("control character in a string");
            if (c != '\\') {
                out += (char)c;
                continue;
            }
            if (p_ >= s_.size()) fail("unterminated string");
            switch (s_[p_++]) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'u': {
                unsigned cp = hex4();
                if (cp >= 0xD800 && cp < 0xDC00 && s_.compare(p_, 2, "\\u") == 0) {
                    p_ += 2;
                    unsigned lo = hex4();
                    if (lo < 0xDC00 || lo >= 0xE000) fail("bad surrogate pair");
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                } else if (cp >= 0xD800 && cp < 0xE000) {
                    fail("lone surrogate");
                }
                utf8(out, cp);
                break;
            }
            default: fail("bad escape");
            }
        }
    }

    // JSON's grammar checked here; strtod then reads exactly that span.
    double number()
    {
        size_t b = p_;
        auto digits = [&] {
            size_t d = p_;
            while (p_ < s_.size() && s_[p_] >= '0' && s_[p_] <= '9') ++p_;
            return p_ > d;
        };
        if (p_ < s_.size() && s_[p_] == '-') ++p_;
        if (!digits()) fail("expected a value");
        if (p_ < s_.size() && s_[p_] == '.') {
            ++p_;
            if (!digits()) fail("bad number");
        }
        if (p_ < s_.size() && (s_[p_] == 'e' || s_[p_] == 'E')) {
            ++p_;
            if (p_ < s_.size() && (s_[p_] == '+' || s_[p_] == '-')) ++p_;
            if (!digits()) fail("bad number");
        }
        std::string span = s_.substr(b, p_ - b);
        double v = std::strtod(span.c_str(), nullptr);
        if (!std::isfinite(v)) fail("number out of range");
        return v;
    }
};

// ---- Reading files ----------------------------------------------------------

// Whole file, refusing more than `cap` bytes so a wrong path cannot make us
// read a huge file into memory.
std::string read_file(const std::string &path, size_t cap)
{
    struct stat st;
    if (stat(path.c_str(), &st) != 0) throw Failure(path + ": " + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) throw Failure(path + ": not a regular file");
    if ((uintmax_t)st.st_size > cap)
        throw Failure(path + ": " + std::to_string((uintmax_t)st.st_size) +
                      " bytes, more than expected (" + std::to_string(cap) + ")");
    std::unique_ptr<FILE, int (*)(FILE *)> f(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!f) throw Failure(path + ": " + std::strerror(errno));
    std::string s((size_t)st.st_size, '\0');
    if (!s.empty() && std::fread(&s[0], 1, s.size(), f.get()) != s.size())
        throw Failure(path + ": read error or file changed while reading");
    return s;
}

uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

float le_float(const unsigned char *p)
{
    uint32_t u = le32(p);
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}

// ---- The manifest, checked ---------------------------------------------------

// Where a value sits in the manifest, for messages: "sets[2].count".
struct Ctx {
    std::string file, path;
    [[noreturn]] void fail(const std::string &what) const
    {
        throw Failure(file + ": " + path + ": " + what);
    }
    Ctx at(const std::string &k) const { return {file, path.empty() ? k : path + "." + k}; }
    Ctx at(size_t i) const { return {file, path + "[" + std::to_string(i) + "]"}; }
};

const Json &member(const Json &o, const Ctx &c, const char *k)
{
    if (o.type != Json::Object) c.fail("expected an object");
    const Json *v = o.get(k);
    if (!v) c.at(k).fail("missing");
    return *v;
}

std::string get_string(const Json &o, const Ctx &c, const char *k)
{
    const Json &v = member(o, c, k);
    if (v.type != Json::String || v.str.empty()) c.at(k).fail("expected a non-empty string");
    return v.str;
}

long long get_int(const Json &o, const Ctx &c, const char *k, long long lo, long long hi)
{
    const Json &v = member(o, c, k);
    if (v.type != Json::Number || v.number != std::floor(v.number) || v.number < (double)lo ||
        v.number > (double)hi)
        c.at(k).fail("expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return (long long)v.number;
}

const Json &get_array(const Json &o, const Ctx &c, const char *k)
{
    const Json &v = member(o, c, k);
    if (v.type != Json::Array) c.at(k).fail("expected an array");
    return v;
}

// A timing object's median, or a negative value for null or absence.
double get_median(const Json *t)
{
    if (!t || t->type != Json::Object) return -1.0;
    const Json *m = t->get("median");
    return m && m->type == Json::Number && m->number > 0.0 ? m->number : -1.0;
}

template <class E> E lookup(const Ctx &c, const std::string &v, const std::map<std::string, E> &m)
{
    auto it = m.find(v);
    if (it == m.end()) c.fail("unknown value '" + v + "'");
    return it->second;
}

struct QuerySet {
    std::string name;
    std::vector<float> q; // count × 6 floats in the order s, t, dsdx, dtdx, dsdy, dtdy
    size_t count = 0;
};

struct Format {
    std::string name, file;
    TextureSystem::TextureHandle *handle = nullptr;
};

struct Filter {
    std::string name;
    TextureOpt opt;
    int nchannels = 4;
};

struct Bench {
    double ours = -1.0, oiio = -1.0; // bench's 1-thread medians, samples/s
};

struct Manifest {
    std::string dir, version, command;
    int texture_size = 0;
    std::vector<QuerySet> sets;
    std::vector<Format> formats;
    std::vector<Filter> filters;
    std::vector<std::string> skipped_names; // filters without an OIIO twin
    std::map<std::string, Bench> bench; // "set/format/filter"
    double load[2] = {-1.0, -1.0};
};

std::string key3(const std::string &a, const std::string &b, const std::string &c)
{
    return a + "/" + b + "/" + c;
}

std::string join(const std::string &dir, const std::string &p)
{
    return p[0] == '/' ? p : dir + "/" + p;
}

// The record layout as the manifest states it; where each of our six
// values sits in a record (index into `fields`).
std::vector<int> record_layout(const Json &root, const Ctx &c0)
{
    static const char *const want[6] = {"s", "t", "dsdx", "dtdx", "dsdy", "dtdy"};
    Ctx c = c0.at("query_file");
    const Json &qf = member(root, c0, "query_file");
    if (get_string(qf, c, "byte_order") != "little-endian")
        c.at("byte_order").fail("only little-endian is read");
    if (get_string(qf, c, "scalar") != "float32") c.at("scalar").fail("only float32 is read");
    const Json &fields = get_array(qf, c, "fields");
    if (fields.items.size() != 6) c.at("fields").fail("expected the six fields s, t, dsdx, dtdx, dsdy, dtdy");
    std::vector<int> pos(6, -1);
    for (size_t i = 0; i < 6; ++i) {
        const Json &f = fields.items[i];
        int k = 0;
        while (k < 6 && !(f.type == Json::String && f.str == want[k])) ++k;
        if (k == 6 || pos[(size_t)k] >= 0) c.at("fields").at(i).fail("unknown or repeated field");
        pos[(size_t)k] = (int)i;
    }
    if (get_int(qf, c, "record_bytes", 1, 1 << 20) != 24)
        c.at("record_bytes").fail("six float32 take 24 bytes");
    return pos;
}

// A query file: exactly count × 24 bytes, decoded into our field order.
void read_queries(QuerySet &qs, const std::string &path, size_t count, const std::vector<int> &pos)
{
    struct stat st;
    if (stat(path.c_str(), &st) != 0) throw Failure(path + ": " + std::strerror(errno));
    // The size is checked before anything is allocated: a garbled count
    // cannot ask for more memory than the file holds.
    if ((uintmax_t)st.st_size != (uintmax_t)count * 24u)
        throw Failure(path + ": " + std::to_string((uintmax_t)st.st_size) + " bytes, but the manifest says " +
                      std::to_string(count) + " queries of 24 bytes (" +
                      std::to_string((uintmax_t)count * 24u) + "): truncated or not this run's file");
    std::string raw = read_file(path, (size_t)st.st_size);
    qs.count = count;
    qs.q.resize(count * 6);
    const unsigned char *p = (const unsigned char *)raw.data();
    for (size_t i = 0; i < count; ++i)
        for (size_t k = 0; k < 6; ++k) qs.q[6 * i + k] = le_float(p + 24 * i + 4 * (size_t)pos[k]);
}

Filter read_filter(const Json &f, const Ctx &c)
{
    static const std::map<std::string, TextureOpt::InterpMode> interp = {
        {"InterpClosest", TextureOpt::InterpClosest},
        {"InterpBilinear", TextureOpt::InterpBilinear},
        {"InterpBicubic", TextureOpt::InterpBicubic},
        {"InterpSmartBicubic", TextureOpt::InterpSmartBicubic},
    };
    static const std::map<std::string, TextureOpt::MipMode> mip = {
        {"MipModeDefault", TextureOpt::MipModeDefault},
        {"MipModeNoMIP", TextureOpt::MipModeNoMIP},
        {"MipModeOneLevel", TextureOpt::MipModeOneLevel},
        {"MipModeTrilinear", TextureOpt::MipModeTrilinear},
        {"MipModeAniso", TextureOpt::MipModeAniso},
    };
    // decode_wrapmode maps any unknown name to WrapDefault (the file's own
    // mode); a typo must not silently become that.
    static const std::map<std::string, int> wraps = {
        {"default", 0}, {"black", 0}, {"clamp", 0}, {"periodic", 0}, {"mirror", 0},
    };
    Filter out;
    out.name = get_string(f, c, "name");
    const Json &o = member(f, c, "oiio");
    Ctx co = c.at("oiio");
    out.opt.interpmode = lookup(co.at("interpmode"), get_string(o, co, "interpmode"), interp);
    out.opt.mipmode = lookup(co.at("mipmode"), get_string(o, co, "mipmode"), mip);
    std::string sw = get_string(o, co, "swrap"), tw = get_string(o, co, "twrap");
    lookup(co.at("swrap"), sw, wraps);
    lookup(co.at("twrap"), tw, wraps);
    out.opt.swrap = TextureOpt::decode_wrapmode(sw.c_str());
    out.opt.twrap = TextureOpt::decode_wrapmode(tw.c_str());
    out.opt.anisotropic = (int)get_int(o, co, "anisotropic", 1, 1 << 16);
    const Json &cons = member(o, co, "conservative_filter");
    if (cons.type != Json::Bool) co.at("conservative_filter").fail("expected true or false");
    out.opt.conservative_filter = cons.boolean;
    out.nchannels = o.get("nchannels") ? (int)get_int(o, co, "nchannels", 1, 4) : 4;
    return out;
}

Manifest read_manifest(const std::string &arg)
{
    Manifest m;
    struct stat st;
    std::string file = arg;
    if (stat(arg.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
        m.dir = arg;
        file = arg + "/manifest.json";
    } else {
        size_t slash = arg.find_last_of('/');
        m.dir = slash == std::string::npos ? "." : arg.substr(0, slash ? slash : 1);
    }
    std::string text = read_file(file, 16u << 20);
    Json root = Parser(text, file).parse();
    Ctx c{file, ""};
    if (root.type != Json::Object) c.fail("the manifest is not a JSON object");
    if (get_int(root, c, "manifest_version", 0, 1 << 30) != 1)
        c.at("manifest_version").fail("this program reads version 1");
    if (const Json *v = root.get("version"); v && v->type == Json::String) m.version = v->str;
    if (const Json *v = root.get("command"); v && v->type == Json::String) m.command = v->str;
    m.texture_size = (int)get_int(root, c, "texture_size", 1, 1 << 20);
    std::vector<int> pos = record_layout(root, c);

    const Json &sets = get_array(root, c, "sets");
    for (size_t i = 0; i < sets.items.size(); ++i) {
        Ctx ci = c.at("sets").at(i);
        QuerySet qs;
        qs.name = get_string(sets.items[i], ci, "name");
        size_t count = (size_t)get_int(sets.items[i], ci, "count", 1, 1LL << 32);
        read_queries(qs, join(m.dir, get_string(sets.items[i], ci, "file")), count, pos);
        m.sets.push_back(std::move(qs));
    }
    const Json &fmts = get_array(root, c, "formats");
    for (size_t i = 0; i < fmts.items.size(); ++i) {
        Ctx ci = c.at("formats").at(i);
        Format f;
        f.name = get_string(fmts.items[i], ci, "name");
        f.file = join(m.dir, get_string(fmts.items[i], ci, "oiio_file"));
        m.formats.push_back(f);
    }
    const Json &filters = get_array(root, c, "filters");
    for (size_t i = 0; i < filters.items.size(); ++i) {
        Ctx ci = c.at("filters").at(i);
        const Json &oiio = member(filters.items[i], ci, "oiio");
        if (oiio.type == Json::Null) {
            m.skipped_names.push_back(get_string(filters.items[i], ci, "name"));
            continue;
        }
        m.filters.push_back(read_filter(filters.items[i], ci));
    }
    if (m.sets.empty() || m.formats.empty() || m.filters.empty())
        c.fail("no set, format or OIIO filter to replay");

    // bench's numbers are optional: a manifest without them still replays.
    if (const Json *t = root.get("timing"); t && t->type == Json::Object) {
        const Json *b = t->get("load_before"), *a = t->get("load_after");
        if (b && b->type == Json::Number) m.load[0] = b->number;
        if (a && a->type == Json::Number) m.load[1] = a->number;
    }
    if (const Json *res = root.get("results"); res && res->type == Json::Array) {
        for (size_t i = 0; i < res->items.size(); ++i) {
            const Json &r = res->items[i];
            Ctx ci = c.at("results").at(i);
            Bench b;
            b.ours = get_median(r.get("ours"));
            b.oiio = get_median(r.get("oiio"));
            m.bench[key3(get_string(r, ci, "set"), get_string(r, ci, "format"),
                         get_string(r, ci, "filter"))] = b;
        }
    }
    return m;
}

// ---- Timing -------------------------------------------------------------------

double now()
{
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

// One pass over every query, one texture() call each, as a renderer's
// shader would make them. Returns seconds.
double pass(TextureSystem *ts, TextureSystem::TextureHandle *h, Filter &f, const QuerySet &qs,
            float *out)
{
    TextureSystem::Perthread *pt = ts->get_perthread_info();
    const float *q = qs.q.data();
    double t0 = now();
    for (size_t i = 0; i < qs.count; ++i, q += 6)
        if (!ts->texture(h, pt, f.opt, q[0], q[1], q[2], q[3], q[4], q[5], f.nchannels,
                         out + (size_t)f.nchannels * i))
            throw Failure("texture() failed on query " + std::to_string(i) + ": " + ts->geterror());
    return now() - t0;
}

struct Timing {
    double median, min, max;
};

Timing time_it(TextureSystem *ts, TextureSystem::TextureHandle *h, Filter &f, const QuerySet &qs,
               int runs, std::vector<float> &out)
{
    std::vector<double> sps;
    out.assign(qs.count * (size_t)f.nchannels, 0.0f);
    pass(ts, h, f, qs, out.data()); // warm-up: reads the tiles into the cache
    for (int r = 0; r < runs; ++r) {
        double s = pass(ts, h, f, qs, out.data());
        sps.push_back((double)qs.count / (s > 0.0 ? s : 1e-9));
    }
    std::sort(sps.begin(), sps.end());
    size_t n = sps.size();
    double med = n % 2 ? sps[n / 2] : 0.5 * (sps[n / 2 - 1] + sps[n / 2]);
    return {med, sps.front(), sps.back()};
}

void dump(const std::string &dir, const std::string &name, const std::vector<float> &v)
{
    std::string path = dir + "/" + name + ".rgba";
    std::vector<unsigned char> b(v.size() * 4);
    for (size_t i = 0; i < v.size(); ++i) {
        uint32_t u;
        std::memcpy(&u, &v[i], 4);
        for (int k = 0; k < 4; ++k) b[4 * i + (size_t)k] = (unsigned char)(u >> (8 * k));
    }
    std::unique_ptr<FILE, int (*)(FILE *)> f(std::fopen(path.c_str(), "wb"), std::fclose);
    bool ok = f && std::fwrite(b.data(), 1, b.size(), f.get()) == b.size();
    if (f) ok = std::fclose(f.release()) == 0 && ok;
    if (!ok) throw Failure("cannot write " + path);
}

// Bytes of the texture files: uncompressed tiles (as bench writes them)
// take about as much memory as they do disk.
double files_mb(const Manifest &m)
{
    double bytes = 0.0;
    for (const Format &f : m.formats) {
        struct stat st;
        if (stat(f.file.c_str(), &st) != 0) throw Failure(f.file + ": " + std::strerror(errno));
        bytes += (double)st.st_size;
    }
    return bytes / (1024.0 * 1024.0);
}

std::string mps(double v)
{
    char b[32];
    if (v > 0.0)
        std::snprintf(b, sizeof b, "%.2f", v * 1e-6);
    else
        std::snprintf(b, sizeof b, "-");
    return b;
}

int replay(const Manifest &m, int runs, const char *dump_dir)
{
    // Large enough that no tile is ever evicted (checked below), so that
    // passes time filtering and cache lookups, never file reads.
    float cache_mb = (float)std::max(4096.0, 2.0 * files_mb(m) + 256.0);
    std::unique_ptr<TextureSystem, void (*)(TextureSystem *)> ts(
        TextureSystem::create(false), [](TextureSystem *t) { TextureSystem::destroy(t); });
    if (!ts) throw Failure("cannot create an OpenImageIO TextureSystem");
    ts->attribute("max_memory_MB", cache_mb);

    std::vector<Format> formats = m.formats;
    for (Format &f : formats) {
        f.handle = ts->get_texture_handle(ustring(f.file));
        ImageSpec spec;
        if (!f.handle || !ts->good(f.handle) || !ts->get_imagespec(f.handle, nullptr, 0, spec)) {
            std::string e = ts->geterror();
            throw Failure(f.file + ": " + (e.empty() ? "cannot open" : e));
        }
    }
    double load0 = -1.0, load1 = -1.0;
    if (getloadavg(&load0, 1) != 1) load0 = -1.0;

    int v = openimageio_version();
    std::printf("oiio_replay: %s (texsample bench %s)\n", m.dir.c_str(),
                m.version.empty() ? "?" : m.version.c_str());
    if (!m.command.empty()) std::printf("recorded by: %s\n", m.command.c_str());
    std::printf("OpenImageIO %d.%d.%d, private TextureSystem, max_memory_MB %.0f; %dx%d textures,\n"
                "1 thread, median [min-max] of %d runs after a warm-up, in millions of samples per second.\n"
                "bench = the numbers in the manifest (1 thread); ratio = bench's ours / OIIO,\n"
                "bench's OIIO or this program's; diff = replay ratio / bench ratio - 1.\n",
                v / 10000, v / 100 % 100, v % 100, (double)cache_mb, m.texture_size, m.texture_size,
                runs);

    std::printf("\n%-15s %-7s %-10s %-21s %-11s %-11s %-13s %-13s %s\n", "set", "format", "filter",
                "replay OIIO", "bench OIIO", "bench ours", "ratio bench", "ratio replay", "diff");
    std::vector<float> out;
    std::vector<Filter> filters = m.filters;
    for (const QuerySet &qs : m.sets)
        for (const Format &f : formats)
            for (Filter &fl : filters) {
                Timing t = time_it(ts.get(), f.handle, fl, qs, runs, out);
                if (dump_dir) dump(dump_dir, qs.name + "_" + f.name + "_" + fl.name, out);
                auto it = m.bench.find(key3(qs.name, f.name, fl.name));
                Bench b = it != m.bench.end() ? it->second : Bench{};
                char cell[64], rb[16] = "-", rr[16] = "-", d[16] = "-";
                std::snprintf(cell, sizeof cell, "%.2f [%.2f-%.2f]", t.median * 1e-6, t.min * 1e-6,
                              t.max * 1e-6);
                if (b.ours > 0.0 && b.oiio > 0.0) std::snprintf(rb, sizeof rb, "%.2f", b.ours / b.oiio);
                if (b.ours > 0.0) std::snprintf(rr, sizeof rr, "%.2f", b.ours / t.median);
                if (b.ours > 0.0 && b.oiio > 0.0)
                    std::snprintf(d, sizeof d, "%+.0f%%", 100.0 * (b.oiio / t.median - 1.0));
                std::printf("%-15s %-7s %-10s %-21s %-11s %-11s %-13s %-13s %s\n", qs.name.c_str(),
                            f.name.c_str(), fl.name.c_str(), cell, mps(b.oiio).c_str(),
                            mps(b.ours).c_str(), rb, rr, d);
                std::fflush(stdout);
            }
    if (getloadavg(&load1, 1) != 1) load1 = -1.0;

    if (!m.skipped_names.empty()) {
        std::printf("\nnot replayed (no OIIO twin):");
        for (const std::string &s : m.skipped_names) std::printf(" %s", s.c_str());
        std::printf("\n");
    }
    int created = 0, current = 0;
    ts->getattribute("stat:tiles_created", created);
    ts->getattribute("stat:tiles_current", current);
    std::printf("\ncache: %d tiles read, %d resident at the end%s\n", created, current,
                created == current ? " (none evicted)" : " (SOME EVICTED: timings include file reads)");
    std::printf("1-minute load average: %.2f before, %.2f after (bench's run: %.2f, %.2f).\n", load0,
                load1, m.load[0], m.load[1]);
    return EXIT_OK;
}

int usage(const char *fmt, const char *arg)
{
    std::fprintf(stderr, "oiio_replay: ");
    std::fprintf(stderr, fmt, arg);
    std::fprintf(stderr, "\n(oiio_replay --help for usage)\n");
    return EXIT_USAGE;
}

} // namespace

int main(int argc, char **argv)
{
    const char *dir = nullptr, *dump_dir = nullptr;
    int runs = 5;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "-h" || a == "--help") {
            std::fputs(help, stdout);
            return EXIT_OK;
        }
    }
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--runs" || a == "--dump") {
            if (i + 1 >= argc) return usage("%s needs a value", argv[i]);
            const char *v = argv[++i];
            if (a == "--dump") {
                if (!*v) return usage("%s needs a directory", "--dump");
                dump_dir = v;
                continue;
            }
            char *end = nullptr;
            errno = 0;
            long n = std::strtol(v, &end, 10);
            if (!*v || *end || errno || n < 1 || n > 1000)
                return usage("--runs must be an integer in [1, 1000], not '%s'", v);
            runs = (int)n;
        } else if (a.size() > 1 && a[0] == '-') {
            return usage("unknown option '%s'", argv[i]);
        } else if (dir) {
            return usage("one directory only ('%s' is a second)", argv[i]);
        } else {
            dir = argv[i];
        }
    }
    if (!dir) return usage("%s", "no directory given");
    try {
        Manifest m = read_manifest(dir);
        if (dump_dir && mkdir(dump_dir, 0777) != 0 && errno != EEXIST)
            throw Failure(std::string("--dump: cannot create ") + dump_dir + ": " + std::strerror(errno));
        return replay(m, runs, dump_dir);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "oiio_replay: %s\n", e.what());
        return EXIT_RUNTIME;
    }
}
