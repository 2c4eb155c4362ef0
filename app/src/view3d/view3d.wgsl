// The 3D view: meshes shaded with flat normals into an offscreen target
// with a depth buffer, then copied into egui's pass.

struct Globals {
    clip_from_world: mat4x4<f32>,
    eye: vec4<f32>,
    light: vec4<f32>,
};

@group(0) @binding(0) var<uniform> globals: Globals;

struct MeshOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) color: vec4<f32>,
};

@vertex
fn vs_mesh(@location(0) position: vec3<f32>, @location(1) color: vec4<f32>) -> MeshOut {
    var out: MeshOut;
    out.clip = globals.clip_from_world * vec4<f32>(position, 1.0);
    out.world = position;
    out.color = color;
    return out;
}

@fragment
fn fs_mesh(in: MeshOut) -> @location(0) vec4<f32> {
    // Flat normals from the screen-space derivatives: meshes need no normal
    // buffer, and faceted patterns show their facets as the printer will.
    var n = normalize(cross(dpdx(in.world), dpdy(in.world)));
    let to_eye = normalize(globals.eye.xyz - in.world);
    // Lit from the side facing the eye, so open shells read from both sides.
    if dot(n, to_eye) < 0.0 {
        n = -n;
    }
    let key = max(dot(n, globals.light.xyz), 0.0);
    let head = max(dot(n, to_eye), 0.0);
    let shade = 0.12 + 0.55 * key + 0.38 * head;
    // Colours arrive in sRGB; light them in linear.
    return vec4<f32>(pow(in.color.rgb, vec3<f32>(2.2)) * shade, 1.0);
}

struct BlitOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@group(0) @binding(0) var picture: texture_2d<f32>;
@group(0) @binding(1) var picture_sampler: sampler;

@vertex
fn vs_blit(@builtin(vertex_index) i: u32) -> BlitOut {
    // One triangle covering the viewport.
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    var out: BlitOut;
    out.clip = vec4<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, 0.0, 1.0);
    out.uv = uv;
    return out;
}

fn gamma_from_linear(c: vec3<f32>) -> vec3<f32> {
    let cutoff = c < vec3<f32>(0.0031308);
    let lower = c * 12.92;
    let higher = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(higher, lower, cutoff);
}

// egui's pass writes gamma values into a plain (non-sRGB) target.
@fragment
fn fs_blit_gamma(in: BlitOut) -> @location(0) vec4<f32> {
    let c = textureSample(picture, picture_sampler, in.uv);
    return vec4<f32>(gamma_from_linear(c.rgb), c.a);
}

// An sRGB target encodes on write.
@fragment
fn fs_blit_linear(in: BlitOut) -> @location(0) vec4<f32> {
    return textureSample(picture, picture_sampler, in.uv);
}
