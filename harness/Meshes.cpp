#include "Meshes.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <utility>

namespace osshar {

namespace {

struct Builder
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec3Array> n = new osg::Vec3Array;
    osg::ref_ptr<osg::DrawElementsUInt> idx = new osg::DrawElementsUInt(GL_TRIANGLES);

    unsigned int add(const osg::Vec3& p, const osg::Vec3& normal)
    {
        v->push_back(p);
        n->push_back(normal);
        return static_cast<unsigned int>(v->size() - 1);
    }
    void tri(unsigned int a, unsigned int b, unsigned int c) { idx->push_back(a), idx->push_back(b), idx->push_back(c); }
    void quad(unsigned int a, unsigned int b, unsigned int c, unsigned int d) { tri(a, b, c), tri(a, c, d); }

    osg::ref_ptr<osg::Geometry> geometry(const char* name) { return triangleMesh(name, v.get(), n.get(), idx.get()); }
};

} // namespace

osg::ref_ptr<osg::Geometry> triangleMesh(const char* name, osg::Vec3Array* vertices, osg::Vec3Array* normals,
                                         osg::DrawElementsUInt* triangles)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setName(name);
    g->setVertexArray(vertices);
    g->setNormalArray(normals, osg::Array::BIND_PER_VERTEX);
    g->addPrimitiveSet(triangles);
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);
    return g;
}

osg::ref_ptr<osg::Geometry> makeBox(const osg::Vec3& c, const osg::Vec3& size)
{
    Builder b;
    const osg::Vec3 h = size * 0.5f;
    // Each face: normal axis, then two tangent axes forming a right-handed frame.
    const osg::Vec3 axes[3] = {osg::Vec3(1, 0, 0), osg::Vec3(0, 1, 0), osg::Vec3(0, 0, 1)};
    for (int a = 0; a < 3; ++a)
    {
        for (float s : {1.0f, -1.0f})
        {
            const osg::Vec3 nrm = axes[a] * s;
            const osg::Vec3 u = axes[(a + 1) % 3] * s;
            const osg::Vec3 w = axes[(a + 2) % 3];
            const osg::Vec3 centre = c + osg::Vec3(nrm.x() * h.x(), nrm.y() * h.y(), nrm.z() * h.z());
            const osg::Vec3 du(u.x() * h.x(), u.y() * h.y(), u.z() * h.z());
            const osg::Vec3 dw(w.x() * h.x(), w.y() * h.y(), w.z() * h.z());
            b.quad(b.add(centre - du - dw, nrm), b.add(centre + du - dw, nrm), b.add(centre + du + dw, nrm),
                   b.add(centre - du + dw, nrm));
        }
    }
    return b.geometry("box");
}

osg::ref_ptr<osg::Geometry> makeCylinder(const osg::Vec3& c, float r, float h, unsigned int segments)
{
    Builder b;
    const unsigned int s = std::max(3u, segments);
    const unsigned int bottomCentre = b.add(c, osg::Vec3(0, 0, -1));
    const unsigned int topCentre = b.add(c + osg::Vec3(0, 0, h), osg::Vec3(0, 0, 1));
    unsigned int first = 0;
    for (unsigned int i = 0; i <= s; ++i)
    {
        const double t = 2.0 * M_PI * (i % s) / s;
        const osg::Vec3 radial(std::cos(t), std::sin(t), 0.0f);
        const unsigned int base = b.add(c + radial * r, radial);
        b.add(c + radial * r + osg::Vec3(0, 0, h), radial);
        b.add(c + radial * r, osg::Vec3(0, 0, -1));
        b.add(c + radial * r + osg::Vec3(0, 0, h), osg::Vec3(0, 0, 1));
        if (i == 0)
        {
            first = base;
            continue;
        }
        const unsigned int prev = base - 4;
        b.quad(prev, base, base + 1, prev + 1);
        b.tri(bottomCentre, base + 2, prev + 2);
        b.tri(topCentre, prev + 3, base + 3);
    }
    (void)first;
    return b.geometry("cylinder");
}

osg::ref_ptr<osg::Geometry> makeSphere(const osg::Vec3& c, float r, unsigned int slices, unsigned int stacks)
{
    Builder b;
    slices = std::max(3u, slices), stacks = std::max(2u, stacks);
    for (unsigned int j = 0; j <= stacks; ++j)
    {
        const double phi = M_PI * j / stacks;
        for (unsigned int i = 0; i <= slices; ++i)
        {
            const double t = 2.0 * M_PI * i / slices;
            const osg::Vec3 d(std::sin(phi) * std::cos(t), std::sin(phi) * std::sin(t), std::cos(phi));
            b.add(c + d * r, d);
        }
    }
    const unsigned int row = slices + 1;
    for (unsigned int j = 0; j < stacks; ++j)
        for (unsigned int i = 0; i < slices; ++i)
        {
            const unsigned int a = j * row + i, bb = a + row;
            if (j > 0) b.tri(a, bb, a + 1);
            if (j + 1 < stacks) b.tri(a + 1, bb, bb + 1);
        }
    return b.geometry("sphere");
}

osg::ref_ptr<osg::Geometry> makeTorus(const osg::Vec3& c, float R, float r, unsigned int major, unsigned int minor)
{
    Builder b;
    major = std::max(3u, major), minor = std::max(3u, minor);
    for (unsigned int i = 0; i <= major; ++i)
    {
        const double u = 2.0 * M_PI * i / major;
        const osg::Vec3 radial(std::cos(u), std::sin(u), 0.0f);
        for (unsigned int j = 0; j <= minor; ++j)
        {
            const double w = 2.0 * M_PI * j / minor;
            const osg::Vec3 nrm = radial * std::cos(w) + osg::Vec3(0, 0, std::sin(w));
            b.add(c + radial * R + nrm * r, nrm);
        }
    }
    const unsigned int row = minor + 1;
    for (unsigned int i = 0; i < major; ++i)
        for (unsigned int j = 0; j < minor; ++j)
        {
            const unsigned int a = i * row + j;
            b.quad(a, a + row, a + row + 1, a + 1);
        }
    return b.geometry("torus");
}

osg::ref_ptr<osg::Geometry> makeGround(float cx, float cy, float side, float height)
{
    Builder b;
    const float h = side * 0.5f;
    const osg::Vec3 up(0, 0, 1);
    b.quad(b.add(osg::Vec3(cx - h, cy - h, height), up), b.add(osg::Vec3(cx + h, cy - h, height), up),
           b.add(osg::Vec3(cx + h, cy + h, height), up), b.add(osg::Vec3(cx - h, cy + h, height), up));
    return b.geometry("ground");
}

osg::ref_ptr<osg::Geometry> merge(const osg::Geometry& a, const osg::Geometry& b)
{
    Builder out;
    for (const osg::Geometry* g : {&a, &b})
    {
        const auto& v = static_cast<const osg::Vec3Array&>(*g->getVertexArray());
        const auto& n = static_cast<const osg::Vec3Array&>(*g->getNormalArray());
        const auto& triangles = static_cast<const osg::DrawElementsUInt&>(*g->getPrimitiveSet(0));
        const unsigned int base = static_cast<unsigned int>(out.v->size());
        for (std::size_t i = 0; i < v.size(); ++i) out.add(v[i], n[i]);
        for (unsigned int i : triangles) out.idx->push_back(base + i);
    }
    return out.geometry("merged");
}

osg::ref_ptr<osg::Geometry> readOff(const std::string& path, std::string& error)
{
    std::ifstream in(path);
    std::string magic;
    long long nv = 0, nf = 0, ne = 0;
    if (!(in >> magic) || magic != "OFF" || !(in >> nv >> nf >> ne) || nv < 3 || nf < 1)
    {
        error = "'" + path + "' is not an OFF file";
        return nullptr;
    }
    Builder b;
    for (long long i = 0; i < nv; ++i)
    {
        double x, y, z;
        if (!(in >> x >> y >> z))
        {
            error = "'" + path + "': truncated vertex list";
            return nullptr;
        }
        b.add(osg::Vec3(float(x), float(y), float(z)), osg::Vec3());
    }
    for (long long f = 0; f < nf; ++f)
    {
        int count = 0;
        std::vector<unsigned int> poly;
        if (!(in >> count) || count < 3)
        {
            error = "'" + path + "': malformed face " + std::to_string(f);
            return nullptr;
        }
        for (int k = 0; k < count; ++k)
        {
            long long i = -1;
            if (!(in >> i) || i < 0 || i >= nv)
            {
                error = "'" + path + "': face " + std::to_string(f) + " has a bad vertex index";
                return nullptr;
            }
            poly.push_back(static_cast<unsigned int>(i));
        }
        for (int k = 1; k + 1 < count; ++k) b.tri(poly[0], poly[k], poly[k + 1]);
    }
    return b.geometry("off mesh");
}

osg::ref_ptr<osg::Geometry> subdivideMidpoint(const osg::Geometry& mesh, unsigned int levels)
{
    const osg::Vec3Array* source = dynamic_cast<const osg::Vec3Array*>(mesh.getVertexArray());
    const osg::DrawElementsUInt* sourceIdx =
        mesh.getNumPrimitiveSets() ? dynamic_cast<const osg::DrawElementsUInt*>(mesh.getPrimitiveSet(0)) : nullptr;
    if (!source || !sourceIdx) return nullptr;
    std::vector<osg::Vec3> v(source->begin(), source->end());
    std::vector<unsigned int> t(sourceIdx->begin(), sourceIdx->end());
    for (unsigned int level = 0; level < levels; ++level)
    {
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> midpoints;
        auto mid = [&](unsigned int a, unsigned int b) {
            const auto key = std::minmax(a, b);
            auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            v.push_back((v[a] + v[b]) * 0.5f);
            const unsigned int m = static_cast<unsigned int>(v.size() - 1);
            midpoints.emplace(key, m);
            return m;
        };
        std::vector<unsigned int> next;
        next.reserve(t.size() * 4);
        for (std::size_t i = 0; i + 2 < t.size(); i += 3)
        {
            const unsigned int a = t[i], b = t[i + 1], c = t[i + 2];
            const unsigned int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            for (unsigned int k : {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca}) next.push_back(k);
        }
        t.swap(next);
    }
    std::vector<osg::Vec3> normals(v.size());
    for (std::size_t i = 0; i + 2 < t.size(); i += 3)
    {
        const osg::Vec3 n = (v[t[i + 1]] - v[t[i]]) ^ (v[t[i + 2]] - v[t[i]]); // area-weighted
        for (int k = 0; k < 3; ++k) normals[t[i + k]] += n;
    }
    Builder b;
    for (std::size_t i = 0; i < v.size(); ++i)
    {
        osg::Vec3 n = normals[i];
        n.normalize();
        b.add(v[i], n);
    }
    b.idx->assign(t.begin(), t.end());
    return b.geometry("subdivided mesh");
}

} // namespace osshar
