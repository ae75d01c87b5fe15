#version 450
// GL backend test: an integer pattern from gl_FragCoord for R32UI targets.
layout(location = 0) out uint outValue;
void main() {
    uvec2 p = uvec2(gl_FragCoord.xy);
    outValue = p.x + 1000u * p.y + 7u;
}
