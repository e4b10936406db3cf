#include "editor/viewport/AgentShaders.h"

namespace throng::editor::shaders {

// Heading h turns the glyph's +x nose to (cos h, 0, -sin h): counter-clockwise about +y
// seen from above, as the scene defines headings. u_bird: the mesh is BirdGlyphMesh's.
const char* const kGlyphVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_part;
layout(location = 3) in vec4 i_positionHeading;
layout(location = 4) in vec4 i_radiusColour;
uniform mat4 u_viewProjection;
uniform float u_minRadiusAtW1;
uniform float u_heightScale;
uniform bool u_bird;
out vec3 v_colour;
out vec3 v_normal;
flat out int v_part;
void main()
{
    vec3 centre = i_positionHeading.xyz;
    float c = cos(i_positionHeading.w), s = sin(i_positionHeading.w);
    float w = (u_viewProjection * vec4(centre, 1.0)).w;
    float radius = max(i_radiusColour.x, u_minRadiusAtW1 * w);
    // A bird's y is in units of its (widened) radius: the same shape at any distance.
    float height = u_heightScale * (u_bird ? radius : clamp(5.5 * i_radiusColour.x, 0.5, 1.8));
    vec2 local = a_position.xz * radius;
    vec3 p = centre + vec3(local.x * c + local.y * s, a_position.y * height, -local.x * s + local.y * c);
    v_normal = vec3(a_normal.x * c + a_normal.z * s, a_normal.y, -a_normal.x * s + a_normal.z * c);
    v_colour = i_radiusColour.yzw;
    v_part = int(a_part + 0.5);
    gl_Position = u_viewProjection * vec4(p, 1.0);
}
)";

const char* const kGlyphFragment = R"(#version 330 core
in vec3 v_colour;
in vec3 v_normal;
flat in int v_part;
uniform bool u_lit;
uniform vec3 u_noseColour;
out vec4 o_colour;
void main()
{
    vec3 colour = v_part == 2 ? u_noseColour : (v_part == 1 ? v_colour * 0.55 : v_colour);
    if (u_lit) {
        vec3 light = normalize(vec3(0.35, 1.0, 0.25));
        colour *= 0.45 + 0.55 * max(dot(normalize(v_normal), light), 0.0);
    }
    o_colour = vec4(colour, 1.0);
}
)";

// The glyph as seen from afar, on screen in pixels (y up): the body from its base b to
// its top t, a half width a (never under u_minRadiusPx, like the glyph), and the cap an
// ellipse of half height c around t (c = a seen from straight above: a disc in the top
// view, where b = t). One quad per agent (gl_VertexID 0..5, two triangles) just around
// that silhouette, all at the depth of the body's middle.
const char* const kImpostorVertex = R"(#version 330 core
layout(location = 3) in vec4 i_positionHeading;
layout(location = 4) in vec4 i_radiusColour;
uniform mat4 u_viewProjection;
uniform vec2 u_halfViewportPx;
uniform float u_metresPerPixel;
uniform float u_minRadiusPx;
uniform float u_heightScale;
uniform vec3 u_eye;
out vec3 v_colour;
out vec2 v_p;                // this corner relative to the body's middle, px
flat out vec2 v_shape;       // a, c; px
flat out vec4 v_axis;        // b and t relative to the body's middle; px
flat out vec4 v_frame;       // heading along screen right and away; light along right and toward
const vec2 kCorners[6] = vec2[6](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
void main()
{
    vec3 base = i_positionHeading.xyz;
    float radiusM = i_radiusColour.x;
    float heightM = u_heightScale * clamp(5.5 * radiusM, 0.5, 1.8);
    vec4 cb = u_viewProjection * vec4(base, 1.0);
    vec4 ct = u_viewProjection * vec4(base + vec3(0.0, heightM, 0.0), 1.0);
    vec4 cm = u_viewProjection * vec4(base + vec3(0.0, 0.5 * heightM, 0.0), 1.0);
    v_colour = i_radiusColour.yzw;
    if (cb.w <= 1e-6 || ct.w <= 1e-6) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // behind the eye: clipped
        return;
    }
    vec2 b = cb.xy / cb.w * u_halfViewportPx, t = ct.xy / ct.w * u_halfViewportPx;
    vec2 m = cm.xy / cm.w * u_halfViewportPx;
    float a = max(radiusM / (cb.w * u_metresPerPixel), u_minRadiusPx);
    bool standing = u_heightScale > 0.0;
    vec2 away = standing ? base.xz - u_eye.xz : vec2(0.0, -1.0);
    away = dot(away, away) > 1e-12 ? normalize(away) : vec2(0.0, -1.0);
    vec2 right = vec2(-away.y, away.x);
    float c = standing ? a * abs(normalize(base - u_eye).y) : a;
    vec2 lo = min(b, t) - m - vec2(a, c) - 0.5, hi = max(b, t) - m + vec2(a, c) + 0.5;
    vec2 corner = kCorners[gl_VertexID];
    v_p = mix(lo, hi, 0.5 * corner + 0.5);
    gl_Position = vec4((m + v_p) / u_halfViewportPx * cm.w, cm.z, cm.w);
    v_shape = vec2(a, c);
    v_axis = vec4(b - m, t - m);
    vec2 heading = vec2(cos(i_positionHeading.w), -sin(i_positionHeading.w));
    vec3 light = normalize(vec3(0.35, 1.0, 0.25));
    v_frame = vec4(dot(heading, right), dot(heading, away), dot(right, light.xz), -dot(away, light.xz));
}
)";

// Inside the cap: the body colour with the nose wedge (kNoseFrom..kNoseTo along the
// heading, as AgentGlyphMesh); below it the side of a cylinder, shaded as the prism's.
const char* const kImpostorFragment = R"(#version 330 core
in vec3 v_colour;
in vec2 v_p;
flat in vec2 v_shape;
flat in vec4 v_axis;
flat in vec4 v_frame;
uniform bool u_lit;
uniform vec3 u_noseColour;
out vec4 o_colour;
void main()
{
    float a = v_shape.x, c = max(v_shape.y, 1e-3);
    vec2 p = v_p;
    vec2 b = v_axis.xy, t = v_axis.zw;
    float along = clamp((p.y - b.y) / max(t.y - b.y, 1e-3), 0.0, 1.0);
    float x = (p.x - mix(b.x, t.x, along)) / a;
    if (abs(x) > 1.0)
        discard;
    vec2 q = vec2(x, (p.y - t.y) / c);
    vec3 colour;
    if (dot(q, q) <= 1.0) {
        float s = q.x * v_frame.x + q.y * v_frame.y;
        float u = -q.x * v_frame.y + q.y * v_frame.x;
        bool nose = s >= 0.30 && s <= 0.96 && abs(u) <= 0.42 * (0.96 - s) / 0.66;
        colour = nose ? u_noseColour : v_colour;
        if (u_lit)
            colour *= 0.45 + 0.55 * normalize(vec3(0.35, 1.0, 0.25)).y;
    } else if (p.y < t.y && p.y >= b.y - c * sqrt(1.0 - x * x)) {
        colour = v_colour;
        if (u_lit)
            colour *= 0.45 + 0.55 * max(x * v_frame.z + sqrt(1.0 - x * x) * v_frame.w, 0.0);
    } else {
        discard;
    }
    o_colour = vec4(colour, 1.0);
}
)";

}  // namespace throng::editor::shaders
