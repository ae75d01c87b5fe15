#include "obj_mesh.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <fstream>
#include <iterator>

namespace sfx::samples {

Result<Mesh> parseObj(const std::string& path, const std::string& text) {
    tinyobj::ObjReader reader;
    tinyobj::ObjReaderConfig config;
    config.vertex_color = false;
    // No material files: the samples shade with their own albedo.
    if (!reader.ParseFromString(text, "", config)) return Status{StatusCode::FileError, path + ": " + reader.Error()};
    const auto& attrib = reader.GetAttrib();
    auto error = [&](const std::string& what) { return Status{StatusCode::FileError, path + ": " + what}; };
    Mesh m;
    m.vertices.resize(attrib.vertices.size() / 3);
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        const glm::vec3 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
        // A non-finite position would make every normal it touches NaN.
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return error("vertex " + std::to_string(i + 1) + " is not finite");
        m.vertices[i] = {p, glm::vec3(0)};
    }
    // tinyobjloader triangulates polygons and resolves relative (negative) indices, but it
    // neither checks an index against the vertex count nor drops faces of 1 or 2 vertices.
    for (const auto& shape : reader.GetShapes()) {
        size_t next = 0;
        for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            const size_t count = shape.mesh.num_face_vertices[f];
            if (count != 3) return error("face " + std::to_string(f + 1) + " of '" + shape.name + "' has " + std::to_string(count) + " vertices");
            if (next + count > shape.mesh.indices.size()) return error("face " + std::to_string(f + 1) + " of '" + shape.name + "' is cut short");
            for (size_t k = 0; k < count; ++k) {
                const int index = shape.mesh.indices[next + k].vertex_index;
                if (index < 0 || size_t(index) >= m.vertices.size())
                    return error("face " + std::to_string(f + 1) + " of '" + shape.name + "' refers to vertex " + std::to_string(int64_t(index) + 1) +
                                 "; the file has " + std::to_string(m.vertices.size()));
                m.indices.push_back(uint32_t(index));
            }
            next += count;
        }
    }
    // The OBJ has no normals: area-weighted smooth vertex normals from the faces, summed in
    // double precision: in float, the cross product of edges near FLT_MAX overflows to
    // infinity and the normal comes out NaN.
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

Result<Mesh> loadObj(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Status{StatusCode::FileError, path + ": cannot open for reading"};
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return Status{StatusCode::FileError, path + ": read failed"};
    return parseObj(path, text);
}

}  // namespace sfx::samples
