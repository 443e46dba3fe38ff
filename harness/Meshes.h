// Closed, welded triangle meshes generated in code, with per-vertex normals.
#ifndef OSS_HARNESS_MESHES_H
#define OSS_HARNESS_MESHES_H

#include <osg/Geometry>

#include <string>

namespace osshar {

/** An indexed triangle mesh of these arrays (per-vertex normals), drawn from vertex buffer
 *  objects, as every shape here is made. */
osg::ref_ptr<osg::Geometry> triangleMesh(const char* name, osg::Vec3Array* vertices, osg::Vec3Array* normals,
                                         osg::DrawElementsUInt* triangles);

/** An axis-aligned box, centre c, full extents size; 24 vertices (flat faces), 12 triangles. */
osg::ref_ptr<osg::Geometry> makeBox(const osg::Vec3& c, const osg::Vec3& size);

/** A closed cylinder along z from base centre c, radius r, height h, with `segments` sides. */
osg::ref_ptr<osg::Geometry> makeCylinder(const osg::Vec3& c, float r, float h, unsigned int segments);

/** A UV sphere, centre c, radius r (slices around z, stacks from pole to pole). */
osg::ref_ptr<osg::Geometry> makeSphere(const osg::Vec3& c, float r, unsigned int slices, unsigned int stacks);

/** A torus around the z axis: major radius R, minor radius r. */
osg::ref_ptr<osg::Geometry> makeTorus(const osg::Vec3& c, float R, float r, unsigned int major, unsigned int minor);

/** A square in the plane z = height, facing +z, of side `side` centred on (cx, cy). */
osg::ref_ptr<osg::Geometry> makeGround(float cx, float cy, float side, float height = 0.0f);
/** One geometry holding the triangles of a and b, both made by the functions here (vertices,
 *  per-vertex normals, one DrawElementsUInt of triangles). */
osg::ref_ptr<osg::Geometry> merge(const osg::Geometry& a, const osg::Geometry& b);

/** A triangle mesh read from an OFF file (polygons fanned into triangles), or null with a
 *  message in error. Vertices welded as the file gives them; no normals. */
osg::ref_ptr<osg::Geometry> readOff(const std::string& path, std::string& error);

/** Splits every triangle of an indexed triangle mesh into four at its edge midpoints (shared
 *  edges share their midpoint), `levels` times, and sets smooth per-vertex normals. */
osg::ref_ptr<osg::Geometry> subdivideMidpoint(const osg::Geometry& mesh, unsigned int levels);

} // namespace osshar

#endif
