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
    // The OBJ has no normals: area-weighted smooth vertex normals from the faces.
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        Vertex &a = m.vertices[m.indices[t]], &b = m.vertices[m.indices[t + 1]], &c = m.vertices[m.indices[t + 2]];
        const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
        a.normal += n;
        b.normal += n;
        c.normal += n;
    }
    for (Vertex& v : m.vertices) v.normal = glm::length(v.normal) > 0 ? glm::normalize(v.normal) : glm::vec3(0, 1, 0);
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
