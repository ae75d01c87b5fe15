#include "sfx/mesh_primitives.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace sfx::scene {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

void addQuad(TriangleMesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    const glm::vec3 n = glm::normalize(glm::cross(b - a, d - a));
    const uint32_t base = uint32_t(m.vertices.size());
    for (glm::vec3 p : {a, b, c, d}) m.vertices.push_back({p, n});
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

TriangleMesh quadMesh() {
    TriangleMesh m;
    addQuad(m, {-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0});
    return m;
}

TriangleMesh boxMesh(glm::vec3 lo, glm::vec3 hi) {
    TriangleMesh m;
    const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    addQuad(m, p[4], p[5], p[6], p[7]);  // +z
    addQuad(m, p[1], p[0], p[3], p[2]);  // -z
    addQuad(m, p[5], p[1], p[2], p[6]);  // +x
    addQuad(m, p[0], p[4], p[7], p[3]);  // -x
    addQuad(m, p[7], p[6], p[2], p[3]);  // +y
    addQuad(m, p[0], p[1], p[5], p[4]);  // -y
    return m;
}

TriangleMesh sphereMesh(glm::vec3 centre, float radius, int slices, int stacks) {
    TriangleMesh m;
    for (int i = 0; i <= stacks; ++i) {
        const double v = double(i) / stacks, phi = v * kPi;
        for (int j = 0; j <= slices; ++j) {
            const double u = double(j) / slices, theta = u * 2.0 * kPi;
            const glm::vec3 n(float(std::sin(phi) * std::cos(theta)), float(std::cos(phi)), float(std::sin(phi) * std::sin(theta)));
            m.vertices.push_back({centre + radius * n, n});
        }
    }
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const uint32_t a = uint32_t(i * (slices + 1) + j), b = a + uint32_t(slices + 1);
            m.indices.insert(m.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    return m;
}

TriangleMesh cylinderMesh(glm::vec3 base, float radius, float height, int slices, bool capped) {
    TriangleMesh m;
    for (int j = 0; j <= slices; ++j) {
        const double theta = 2.0 * kPi * j / slices;
        const glm::vec3 n(float(std::cos(theta)), 0.0f, float(std::sin(theta)));
        m.vertices.push_back({base + radius * n, n});
        m.vertices.push_back({base + radius * n + glm::vec3(0, height, 0), n});
    }
    for (int j = 0; j < slices; ++j) {
        const uint32_t a = uint32_t(2 * j);
        m.indices.insert(m.indices.end(), {a, a + 1, a + 2, a + 1, a + 3, a + 2});
    }
    if (!capped) return m;
    for (const float y : {0.0f, height}) {
        const glm::vec3 n(0.0f, y > 0 ? 1.0f : -1.0f, 0.0f);
        const uint32_t centre = uint32_t(m.vertices.size());
        m.vertices.push_back({base + glm::vec3(0, y, 0), n});
        for (int j = 0; j <= slices; ++j) {
            const double theta = 2.0 * kPi * j / slices;
            m.vertices.push_back({base + glm::vec3(float(radius * std::cos(theta)), y, float(radius * std::sin(theta))), n});
        }
        for (int j = 0; j < slices; ++j) {
            const uint32_t a = centre + 1 + uint32_t(j);
            if (y > 0)
                m.indices.insert(m.indices.end(), {centre, a + 1, a});
            else
                m.indices.insert(m.indices.end(), {centre, a, a + 1});
        }
    }
    return m;
}

Result<TriangleMesh> parseObjMesh(const std::string& path, const std::string& text) {
    tinyobj::ObjReader reader;
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = "";  // materials are not read: colour comes from the scene
    if (!reader.ParseFromString(text, "", config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        return Status{StatusCode::FileError, path + ": not a readable OBJ file" + (why.empty() ? "" : " (" + why + ")")};
    }
    auto error = [&](const std::string& what) { return Status{StatusCode::FileError, path + ": " + what}; };
    const auto& attrib = reader.GetAttrib();
    TriangleMesh m;
    m.vertices.resize(attrib.vertices.size() / 3);
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        const glm::vec3 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
        // A non-finite position would make every normal it touches NaN.
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return error("vertex " + std::to_string(i + 1) + " is not finite");
        m.vertices[i] = {p, glm::vec3(0)};
    }
    // tinyobjloader triangulates polygons and resolves relative (negative) indices, but it
    // neither checks an index against the vertex count nor drops faces of 1 or 2 vertices.
    for (const auto& shape : reader.GetShapes()) {
        const std::string mesh = shape.name.empty() ? "the mesh" : "'" + shape.name + "'";
        size_t next = 0;
        for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            const size_t count = shape.mesh.num_face_vertices[f];
            if (count != 3) return error("face " + std::to_string(f + 1) + " of " + mesh + " has " + std::to_string(count) + " vertices");
            if (next + count > shape.mesh.indices.size()) return error("face " + std::to_string(f + 1) + " of " + mesh + " is cut short");
            for (size_t k = 0; k < count; ++k) {
                const int index = shape.mesh.indices[next + k].vertex_index;
                if (index < 0 || size_t(index) >= m.vertices.size())
                    return error("face " + std::to_string(f + 1) + " of " + mesh + " refers to vertex " + std::to_string(int64_t(index) + 1) +
                                 "; the file has " + std::to_string(m.vertices.size()));
                m.indices.push_back(uint32_t(index));
            }
            next += count;
        }
    }
    if (m.indices.empty()) return error("no triangles");
    // Smooth vertex normals from the faces, area-weighted (the normals an OBJ may carry are not
    // read), summed in double precision: in float, the cross product of edges near FLT_MAX
    // overflows to infinity and the normal comes out NaN.
    std::vector<glm::dvec3> normals(m.vertices.size(), glm::dvec3(0.0));
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const uint32_t ia = m.indices[t], ib = m.indices[t + 1], ic = m.indices[t + 2];
        const glm::dvec3 a(m.vertices[ia].position), b(m.vertices[ib].position), c(m.vertices[ic].position);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        normals[ia] += n;
        normals[ib] += n;
        normals[ic] += n;
    }
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        const double length = glm::length(normals[i]);
        m.vertices[i].normal = length > 0 && std::isfinite(length) ? glm::vec3(normals[i] / length) : glm::vec3(0, 1, 0);
    }
    return m;
}

Result<TriangleMesh> loadObjMesh(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return Status{StatusCode::FileError, path + ": no such file"};
    std::ifstream in(path, std::ios::binary);
    if (!in) return Status{StatusCode::FileError, path + ": cannot open for reading"};
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return Status{StatusCode::FileError, path + ": read failed"};
    return parseObjMesh(path, text);
}

}  // namespace sfx::scene
