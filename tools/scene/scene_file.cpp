#include "sfx/scene_file.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <new>
#include <set>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "sfx/settings_ranges.hpp"

namespace sfx::scene {
namespace {

using json = nlohmann::json;
using glm::dvec3;

// Inside the loader a problem unwinds to loadSceneFromString as this, which returns its Status:
// nothing of a half-read scene escapes.
struct SceneError {
    Status status;
};

constexpr double kMaxCoordinate = 1.0e6;
constexpr double kMaxColor = 65504.0;  // fp16's largest: every target format holds it
constexpr size_t kMaxFileBytes = size_t(64) << 20;
constexpr const char* kMeshAllowed = "quad, box, sphere, or the path of an .obj file relative to the scene file";

// A value as a message shows it: its JSON text, shortened. Nested values are only named (a
// deeply nested one would recurse through dump()).
std::string describe(const json& v) {
    if (v.is_object()) return "an object";
    if (v.is_array()) {
        for (const json& e : v)
            if (e.is_structured()) return "an array of " + std::to_string(v.size()) + " elements";
        if (v.size() > 8) return "an array of " + std::to_string(v.size()) + " elements";
    }
    std::string s = v.dump();
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return s;
}

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

class Reader {
public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
        throw SceneError{Status{StatusCode::InvalidArgument, file_ + ": " + path + " " + problem}};
    }
    [[noreturn]] void outOfRange(const std::string& path, const json& v, const std::string& allowed) const {
        fail(path, "is " + describe(v) + "; allowed " + allowed);
    }

    // An object whose keys all come from `allowed`.
    void requireObject(const json& v, const std::string& path, std::initializer_list<const char*> allowed) const {
        if (!v.is_object()) outOfRange(path.empty() ? "the document" : path, v, "an object");
        std::string list;
        for (const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
        for (const auto& item : v.items()) {
            bool known = false;
            for (const char* k : allowed) known = known || item.key() == k;
            if (!known) fail(join(path, item.key()), "is not a known key; allowed keys: " + list);
        }
    }
    const json& required(const json& object, const std::string& path, const char* key) const {
        auto it = object.find(key);
        if (it == object.end()) fail(join(path, key), "is missing (required)");
        return *it;
    }
    static const json* optional(const json& object, const char* key) {
        auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    // A finite number in [lo, hi] (or (lo, hi] with openLow, [lo, hi) with openHigh).
    double number(const json& v, const std::string& path, double lo, double hi, const std::string& allowed, bool openLow = false,
                  bool openHigh = false) const {
        if (!v.is_number()) outOfRange(path, v, "a number in " + allowed);
        const double x = v.get<double>();
        const bool low = openLow ? x > lo : x >= lo, high = openHigh ? x < hi : x <= hi;
        if (!std::isfinite(x) || !low || !high) outOfRange(path, v, allowed);
        return x;
    }
    dvec3 vec3(const json& v, const std::string& path, double lo, double hi, const std::string& allowed, bool openLow = false) const {
        if (!v.is_array() || v.size() != 3) outOfRange(path, v, "an array of 3 numbers, each in " + allowed);
        dvec3 out;
        for (int i = 0; i < 3; ++i) out[i] = number(v[size_t(i)], path + "[" + std::to_string(i) + "]", lo, hi, allowed, openLow);
        return out;
    }
    uint32_t size(const json& v, const std::string& path) const {
        const std::string allowed = "an integer in [1, " + std::to_string(kMaxSceneSize) + "]";
        if (v.is_number_unsigned()) {
            const uint64_t n = v.get<uint64_t>();
            if (n >= 1 && n <= kMaxSceneSize) return uint32_t(n);
        }
        outOfRange(path, v, allowed);
    }
    std::string string(const json& v, const std::string& path, const std::string& allowed) const {
        if (!v.is_string() || v.get_ref<const std::string&>().empty()) outOfRange(path, v, allowed);
        return v.get<std::string>();
    }

    const std::string& file() const { return file_; }

private:
    std::string file_;
};

SceneCamera readCamera(const Reader& r, const json& v) {
    const std::string path = "camera";
    r.requireObject(v, path, {"position", "target", "up", "fovY", "near", "far"});
    const std::string coordinates = "[-1e6, 1e6]";
    SceneCamera c;
    c.position = r.vec3(r.required(v, path, "position"), path + ".position", -kMaxCoordinate, kMaxCoordinate, coordinates);
    c.target = r.vec3(r.required(v, path, "target"), path + ".target", -kMaxCoordinate, kMaxCoordinate, coordinates);
    if (const json* up = Reader::optional(v, "up")) c.up = r.vec3(*up, path + ".up", -kMaxCoordinate, kMaxCoordinate, coordinates);
    if (const json* f = Reader::optional(v, "fovY")) c.fovYDegrees = r.number(*f, path + ".fovY", 0.0, 180.0, "(0, 180) degrees", true, true);
    if (const json* n = Reader::optional(v, "near")) c.nearPlane = r.number(*n, path + ".near", 0.0, kMaxCoordinate, "(0, 1e6]", true);
    if (const json* f = Reader::optional(v, "far")) c.farPlane = r.number(*f, path + ".far", 0.0, 1.0e9, "(near, 1e9]", true);
    if (!(c.farPlane > c.nearPlane))
        r.fail(path + ".far", "is " + std::to_string(c.farPlane) + "; allowed greater than camera.near (" + std::to_string(c.nearPlane) + ")");
    const dvec3 forward = c.target - c.position;
    if (!(glm::length(forward) > 1e-9 * std::max(1.0, glm::length(c.position))))
        r.fail(path + ".target", "equals camera.position; allowed any other point");
    const double across = glm::length(glm::cross(glm::normalize(forward), c.up));
    if (!(across > 1e-6 * glm::length(c.up)) || !(glm::length(c.up) > 0.0))
        r.fail(path + ".up",
               "is [" + std::to_string(c.up.x) + ", " + std::to_string(c.up.y) + ", " + std::to_string(c.up.z) +
                   "]; allowed a non-zero vector not parallel to camera.target - camera.position");
    return c;
}

glm::dmat4 worldMatrix(const SceneObject& o) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), o.position);
    m = glm::rotate(m, glm::radians(o.rotationDegrees.z), dvec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(o.rotationDegrees.y), dvec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(o.rotationDegrees.x), dvec3(1, 0, 0));
    return glm::scale(m, o.scale);
}

bool endsWithObj(const std::string& s) {
    if (s.size() < 4) return false;
    std::string ext = s.substr(s.size() - 4);
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return ext == ".obj";
}

class SceneBuilder {
public:
    SceneBuilder(const Reader& r, std::string baseDir) : r_(r), baseDir_(std::move(baseDir)) {}

    SceneObject readObject(const json& v, const std::string& path) {
        r_.requireObject(v, path, {"mesh", "position", "rotation", "scale", "color", "opacity", "shading"});
        SceneObject o;
        o.mesh = r_.string(r_.required(v, path, "mesh"), path + ".mesh", kMeshAllowed);
        o.meshIndex = meshFor(o.mesh, path + ".mesh");
        const std::string coordinates = "[-1e6, 1e6]";
        if (const json* p = Reader::optional(v, "position"))
            o.position = r_.vec3(*p, path + ".position", -kMaxCoordinate, kMaxCoordinate, coordinates);
        if (const json* p = Reader::optional(v, "rotation"))
            o.rotationDegrees = r_.vec3(*p, path + ".rotation", -kMaxCoordinate, kMaxCoordinate, "[-1e6, 1e6] degrees");
        if (const json* s = Reader::optional(v, "scale")) {
            if (s->is_number())
                o.scale = dvec3(r_.number(*s, path + ".scale", 0.0, kMaxCoordinate, "(0, 1e6], or 3 such numbers", true));
            else
                o.scale = r_.vec3(*s, path + ".scale", 0.0, kMaxCoordinate, "(0, 1e6]", true);
        }
        if (const json* c = Reader::optional(v, "color")) o.color = r_.vec3(*c, path + ".color", 0.0, kMaxColor, "[0, 65504] (linear RGB)");
        if (const json* a = Reader::optional(v, "opacity")) {
            const SettingRange& opacity = settingRange(Setting::OitDrawOpacity);  // what the transparency draw takes
            o.opacity = r_.number(*a, path + ".opacity", opacity.min, opacity.max, rangeText(opacity));
        }
        if (const json* s = Reader::optional(v, "shading")) {
            const std::string name = s->is_string() ? s->get<std::string>() : std::string();
            if (name == "lambert")
                o.shading = Shading::Lambert;
            else if (name == "unlit")
                o.shading = Shading::Unlit;
            else
                r_.outOfRange(path + ".shading", *s, "\"lambert\" or \"unlit\"");
        }
        o.world = worldMatrix(o);
        return o;
    }

    std::vector<TriangleMesh> takeMeshes() { return std::move(meshes_); }

private:
    size_t meshFor(const std::string& name, const std::string& path) {
        std::string key = name;
        if (name != "quad" && name != "box" && name != "sphere") {
            if (!endsWithObj(name)) r_.outOfRange(path, json(name), kMeshAllowed);
            const std::filesystem::path p(name);
            key = (p.is_absolute() ? p : std::filesystem::path(baseDir_) / p).lexically_normal().string();
        }
        auto it = index_.find(key);
        if (it != index_.end()) return it->second;
        TriangleMesh mesh;
        if (name == "quad")
            mesh = quadMesh();
        else if (name == "box")
            mesh = boxMesh(glm::vec3(-0.5f), glm::vec3(0.5f));
        else if (name == "sphere")
            mesh = sphereMesh(glm::vec3(0.0f), 0.5f);
        else {
            Result<TriangleMesh> obj = loadObjMesh(key);
            if (!obj)
                throw SceneError{
                    Status{StatusCode::FileError,
                           r_.file() + ": " + path + " '" + name + "' does not load: " + obj.status().message() + "; allowed " + kMeshAllowed}};
            mesh = std::move(obj.value());
        }
        meshes_.push_back(std::move(mesh));
        index_[key] = meshes_.size() - 1;
        return meshes_.size() - 1;
    }

    const Reader& r_;
    std::string baseDir_;
    std::vector<TriangleMesh> meshes_;
    std::map<std::string, size_t> index_;
};

// Line and column (1-based) of a byte offset, for parse errors.
std::string lineColumn(const std::string& text, size_t byte) {
    size_t line = 1, column = 1;
    for (size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

json parseJson(const std::string& text, const std::string& file) {
    // Duplicate keys would silently keep the last value: refuse them.
    std::vector<std::set<std::string>> keys;
    std::string duplicate;
    json::parser_callback_t cb = [&](int, json::parse_event_t event, json& parsed) {
        if (event == json::parse_event_t::object_start)
            keys.emplace_back();
        else if (event == json::parse_event_t::object_end && !keys.empty())
            keys.pop_back();
        else if (event == json::parse_event_t::key && !keys.empty() && duplicate.empty() && parsed.is_string() &&
                 !keys.back().insert(parsed.get<std::string>()).second)
            duplicate = parsed.get<std::string>();
        return true;
    };
    try {
        json doc = json::parse(text, cb, true, false);
        if (!duplicate.empty())
            throw SceneError{Status{StatusCode::FileError, file + ": invalid JSON: the key \"" + duplicate + "\" appears twice in one object"}};
        return doc;
    } catch (const json::parse_error& e) {
        std::string what = e.what();
        // "[json.exception.parse_error.101] parse error at line 4, column 43: syntax error ...":
        // the position is given once, as file:line:column.
        const size_t cut = what.find("] ");
        if (cut != std::string::npos) what = what.substr(cut + 2);
        if (what.rfind("parse error at line", 0) == 0 && what.find(": ") != std::string::npos) what = what.substr(what.find(": ") + 2);
        throw SceneError{Status{StatusCode::FileError, file + ":" + lineColumn(text, e.byte == 0 ? 0 : e.byte - 1) + ": invalid JSON: " + what}};
    }
}

Scene buildScene(const std::string& text, const std::string& baseDir, const std::string& name) {
    const Reader r(name);
    const json doc = parseJson(text, name);
    r.requireObject(doc, "", {"width", "height", "camera", "background", "objects"});
    Scene s;
    s.path = name;
    s.width = r.size(r.required(doc, "", "width"), "width");
    s.height = r.size(r.required(doc, "", "height"), "height");
    s.camera = readCamera(r, r.required(doc, "", "camera"));
    if (const json* b = Reader::optional(doc, "background")) s.background = r.vec3(*b, "background", 0.0, kMaxColor, "[0, 65504] (linear RGB)");
    const json& objects = r.required(doc, "", "objects");
    if (!objects.is_array()) r.outOfRange("objects", objects, "an array of objects");
    SceneBuilder builder(r, baseDir);
    for (size_t i = 0; i < objects.size(); ++i) s.objects.push_back(builder.readObject(objects[i], "objects[" + std::to_string(i) + "]"));
    s.meshes = builder.takeMeshes();
    return s;
}

}  // namespace

const char* toString(Shading shading) { return shading == Shading::Unlit ? "unlit" : "lambert"; }

glm::dmat4 SceneCamera::view() const { return glm::lookAt(position, target, up); }

bool Scene::hasTranslucency() const {
    for (const SceneObject& o : objects)
        if (o.translucent()) return true;
    return false;
}

Result<Scene> loadSceneFromString(const std::string& text, const std::string& baseDir, const std::string& name) {
    try {
        return buildScene(text, baseDir, name);
    } catch (const SceneError& e) {
        return e.status;
    } catch (const std::bad_alloc&) {
        return Status{StatusCode::FileError, name + ": out of memory while reading the scene"};
    } catch (const std::exception& e) {
        return Status{StatusCode::FileError, name + ": " + e.what()};
    }
}

Result<Scene> loadSceneFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return Status{StatusCode::FileError, path + ": no such file"};
    const auto bytes = std::filesystem::file_size(path, ec);
    if (ec || bytes > kMaxFileBytes)
        return Status{StatusCode::FileError, path + ": " + (ec ? "cannot be read" : "is larger than 64 MiB; allowed up to 64 MiB")};
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) return Status{StatusCode::FileError, path + ": cannot be read"};
    std::string dir = std::filesystem::path(path).parent_path().string();
    return loadSceneFromString(text.str(), dir.empty() ? "." : dir, path);
}

}  // namespace sfx::scene
