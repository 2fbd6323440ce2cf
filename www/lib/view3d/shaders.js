// View3D's GLSL ES 3.00 programs: shaded meshes (Blinn-Phong, colour maps), flat lines and round points.

export const MESH_VS = `#version 300 es
layout(location=0) in vec3 aPos;
layout(location=1) in vec3 aNormal;
layout(location=2) in float aScalar;
uniform mat4 uView, uProj;
uniform vec2 uRange;
out vec3 vEye; out vec3 vNormal; out float vT;
void main() {
  vec4 e = uView * vec4(aPos, 1.0);
  vEye = e.xyz;
  vNormal = mat3(uView) * aNormal;
  vT = (aScalar - uRange.x) / (uRange.y - uRange.x);
  gl_Position = uProj * e;
}`;

export const MESH_FS = `#version 300 es
precision highp float;
in vec3 vEye; in vec3 vNormal; in float vT;
uniform vec3 uColor;
uniform float uOpacity;
uniform bool uUseMap;
uniform sampler2D uMap;
out vec4 outColor;
void main() {
  vec3 v = normalize(-vEye);
  vec3 n = vNormal;
  if (dot(n, n) < 1e-20) n = cross(dFdx(vEye), dFdy(vEye));
  n = normalize(n);
  bool back = dot(n, v) < 0.0;
  if (back) n = -n;
  vec3 base = uUseMap ? texture(uMap, vec2(clamp(vT, 0.0, 1.0), 0.5)).rgb : uColor;
  if (back && !uUseMap) base *= 0.78;
  vec3 l = normalize(vec3(-0.35, 0.45, 1.0));          // headlight, slightly above-left of the eye
  vec3 h = normalize(l + v);
  float diff = max(dot(n, l), 0.0);
  float spec = pow(max(dot(n, h), 0.0), 60.0);
  vec3 c = base * (0.30 + 0.70 * diff) + vec3(0.22 * spec);
  outColor = vec4(c * uOpacity, uOpacity);
}`;

// Thick lines: one instance per segment (endpoints aA, aB), expanded to a screen-space quad.
export const LINE_VS = `#version 300 es
layout(location=0) in vec2 aCorner;
layout(location=1) in vec3 aA;
layout(location=2) in vec3 aB;
uniform mat4 uView, uProj;
uniform vec2 uViewport;
uniform float uWidth;
uniform float uBias;
void main() {
  vec4 ca = uProj * uView * vec4(aA, 1.0);
  vec4 cb = uProj * uView * vec4(aB, 1.0);
  vec2 sa = ca.xy / max(ca.w, 1e-6) * uViewport * 0.5;
  vec2 sb = cb.xy / max(cb.w, 1e-6) * uViewport * 0.5;
  vec2 d = sb - sa;
  float len = length(d);
  vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 nrm = vec2(-dir.y, dir.x);
  vec4 c = aCorner.x < 0.5 ? ca : cb;
  vec2 off = (nrm * aCorner.y + dir * (aCorner.x < 0.5 ? -1.0 : 1.0)) * uWidth * 0.5;
  c.xy += off / (uViewport * 0.5) * c.w;
  c.z -= uBias * c.w;
  gl_Position = c;
}`;

export const FLAT_FS = `#version 300 es
precision highp float;
uniform vec4 uColor;
out vec4 outColor;
void main() { outColor = vec4(uColor.rgb * uColor.a, uColor.a); }`;

export const POINT_VS = `#version 300 es
layout(location=0) in vec3 aPos;
layout(location=1) in vec3 aColor;
uniform mat4 uView, uProj;
uniform float uSize;
out vec3 vColor;
void main() {
  gl_Position = uProj * uView * vec4(aPos, 1.0);
  gl_Position.z -= 0.002 * gl_Position.w;
  gl_PointSize = uSize;
  vColor = aColor;
}`;

export const POINT_FS = `#version 300 es
precision highp float;
in vec3 vColor;
uniform float uSize;
uniform float uHighlight;
out vec4 outColor;
void main() {
  vec2 p = gl_PointCoord * 2.0 - 1.0;
  float r = length(p);
  if (r > 1.0) discard;
  float px = 2.0 / uSize;                       // one pixel in point-coordinate units
  float ring = uHighlight > 0.5 ? 1.0 - 5.0 * px : 1.0 - 2.5 * px;
  vec3 c = vColor;
  if (r > ring) c = vec3(0.07);
  else if (uHighlight > 0.5 && r > ring - 3.0 * px) c = vec3(1.0);
  float a = 1.0 - smoothstep(1.0 - px, 1.0, r);
  outColor = vec4(c * a, a);
}`;
