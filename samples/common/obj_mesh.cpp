#include "obj_mesh.hpp"

#include <tiny_obj_loader.h>

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
    Mesh m;
    m.vertices.resize(attrib.vertices.size() / 3);
    for (size_t i = 0; i < m.vertices.size(); ++i)
        m.vertices[i] = {{attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]}, glm::vec3(0)};
    for (const auto& shape : reader.GetShapes())
        for (const auto& idx : shape.mesh.indices) m.indices.push_back(uint32_t(idx.vertex_index));
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
