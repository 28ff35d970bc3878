// Degenerate geometry through the loader and the renderer: zero-area triangles, repeated and
// duplicate vertices, NaN and Inf vertices, inverted and mixed winding, a non-manifold edge, and
// huge and tiny triangles in one scene. The loader drops and counts what cannot be rendered; the
// rest renders with no NaN or Inf in any sample.
#include <doctest/doctest.h>

#include "scene/obj_loader.h"
#include "render_support.h"

using namespace strata;

TEST_CASE("degenerate geometry: dropped and counted at load, never a non-finite sample") {
    const std::string obj =
        "mtllib d.mtl\n"
        "usemtl grey\n"
        // 1-4: a floor (y = 0), counter-clockwise from above
        "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
        "f 1 3 2\nf 1 4 3\n"
        // 5-8: a back wall with mixed winding: one triangle faces the camera, one away
        "v -1 0 1\nv 1 0 1\nv 1 2 1\nv -1 2 1\n"
        "f 5 6 7\nf 5 7 8\n"
        // a zero-area (collinear) triangle, a repeated index, and two duplicate vertices
        "v 0 1 0\nv 0.5 1 0\nv 1 1 0\nv 0.2 0.2 0.2\nv 0.2 0.2 0.2\n"
        "f 9 10 11\nf 9 9 10\nf 12 13 9\n"
        // NaN and Inf vertices (14, 15)
        "v nan 0 0\nv 0 inf 0\n"
        "f 1 2 14\nf 15 2 3\n"
        // a non-manifold edge: three fins share the edge 16-17
        "v 0 0.1 0\nv 0 0.6 0\nv 0.3 0.3 0\nv -0.3 0.3 0\nv 0 0.3 0.3\n"
        "f 16 17 18\nf 16 17 19\nf 17 16 20\n"
        // a huge backdrop (1e6) and a tiny triangle (1e-6) in the middle of the view
        "v -1e6 -1e6 3\nv 1e6 -1e6 3\nv 0 1e6 3\n"
        "v 0.1 0.5 0\nv 0.100001 0.5 0\nv 0.1 0.500001 0\n"
        "f 21 23 22\nf 24 25 26\n"
        "usemtl light\n"
        // 27-30: an emitting ceiling (y = 2) facing down
        "v -1 2 -1\nv 1 2 -1\nv 1 2 1\nv -1 2 1\n"
        "f 27 28 29\nf 27 29 30\n";
    const std::string mtl = "newmtl grey\nKd 0.7 0.7 0.7\nnewmtl light\nKd 0 0 0\nKe 5 5 5\n";
    LoadReport report;
    MeshData mesh = parseObj(obj, "d.obj", mtl, "d.mtl", &report);
    CHECK(report.nonFiniteVertices == 2);
    CHECK(report.droppedTriangles == 5);  // collinear, repeated, duplicate, NaN, Inf
    CHECK(report.faces == 11);  // 16 faces in the file
    CHECK(mesh.triangles.size() == 11);

    const Scene scene(std::move(mesh));
    const Camera camera(CameraPose{{0.0f, 1.0f, -3.0f}, {0.0f, 0.8f, 0.0f}, {0.0f, 1.0f, 0.0f}, 60.0f}, 24, 24);
    for (SamplerKind sampler : {SamplerKind::Uniform, SamplerKind::Strata24}) {
        RenderSettings settings;
        settings.integrator.depth = 6;
        settings.integrator.sampler = sampler;
        settings.seed = 3;
        const AccumulationBuffer buffer = test::renderPasses(scene, camera, settings, 4);
        CHECK(buffer.droppedSamples() == 0);
        CHECK(test::allFinite(buffer));
        // The light is seen (directly or after bounces): the image is not black.
        CHECK(luminance(buffer.imageMean()) > 0.0);
    }
}
