//! The 3D view on the GPU: meshes drawn with a depth buffer and 4× MSAA into
//! an offscreen picture (in the paint callback's `prepare`), which `paint`
//! then copies into egui's pass. Rendering offscreen keeps the view
//! independent of whether egui's own pass has a depth buffer.

use std::collections::HashMap;
use std::sync::Arc;

use eframe::egui_wgpu::{CallbackResources, CallbackTrait, ScreenDescriptor};
use eframe::wgpu::{self, util::DeviceExt};
use glam::{Mat4, Vec3};

use super::view_mesh::ViewMesh;

/// Samples per pixel of the offscreen picture when the view is still. While
/// the camera moves, one sample: on lavapipe that halves the frame time.
const MSAA_SAMPLES: u32 = 4;
/// The offscreen picture's format: linear light stored as sRGB.
const PICTURE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// Samples per pixel of egui's pass, which the copy into it must match:
/// eframe's default (`NativeOptions::multisampling` left at 0, which
/// `main.rs` does) and kittest's are one.
pub const EGUI_PASS_SAMPLES: u32 = 1;
/// Meshes not drawn for this many frames are freed.
const FORGET_AFTER_FRAMES: u64 = 120;

/// One mesh to draw, in a colour (sRGB, 0 to 1).
#[derive(Clone, Debug)]
pub struct Draw {
    /// The triangles.
    pub mesh: Arc<ViewMesh>,
    /// The colour.
    pub rgba: [f32; 4],
}

/// What one view draws in one frame.
#[derive(Clone, Debug)]
pub struct Frame3d {
    /// Which view (several can be on screen).
    pub view_id: u64,
    /// The picture's size, pixels.
    pub size_px: [u32; 2],
    /// World to clip.
    pub clip_from_world: Mat4,
    /// The eye, mm.
    pub eye_mm: Vec3,
    /// Direction towards the key light.
    pub light: Vec3,
    /// Background (sRGB, 0 to 1).
    pub background: [f32; 4],
    /// The meshes.
    pub draws: Vec<Draw>,
    /// Smooth edges with 4× MSAA (off while the camera moves).
    pub antialias: bool,
}

/// The paint callback of one view in one frame.
pub struct View3dCallback {
    /// The frame to draw.
    pub frame: Frame3d,
    /// The format of egui's target.
    pub target_format: wgpu::TextureFormat,
}

impl CallbackTrait for View3dCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &ScreenDescriptor,
        encoder: &mut wgpu::CommandEncoder,
        resources: &mut CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let stale = resources.get::<Renderer3d>().is_some_and(|r| r.target_format != self.target_format);
        if stale || resources.get::<Renderer3d>().is_none() {
            resources.insert(Renderer3d::new(device, self.target_format));
        }
        if let Some(renderer) = resources.get_mut::<Renderer3d>() {
            renderer.render(device, queue, encoder, &self.frame);
        }
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &CallbackResources,
    ) {
        if let Some(renderer) = resources.get::<Renderer3d>() {
            renderer.copy_into(pass, self.frame.view_id);
        }
    }
}

struct GpuMesh {
    source: Arc<ViewMesh>,
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    last_frame: u64,
}

/// The offscreen picture of one view.
struct Targets {
    size_px: [u32; 2],
    color_msaa: wgpu::TextureView,
    depth_msaa: wgpu::TextureView,
    depth: wgpu::TextureView,
    /// The resolved picture, which the copy samples.
    picture: wgpu::TextureView,
    /// Kept so that `Renderer3d::read_back` can copy it out.
    picture_texture: wgpu::Texture,
    copy_bind: wgpu::BindGroup,
    globals: wgpu::Buffer,
    globals_bind: wgpu::BindGroup,
    colors: wgpu::Buffer,
    colors_capacity: usize,
}

/// The 3D view's pipelines, uploaded meshes and offscreen pictures, kept in
/// egui's callback resources.
pub struct Renderer3d {
    target_format: wgpu::TextureFormat,
    /// Drawing with one sample, and with `MSAA_SAMPLES`.
    mesh_pipelines: [wgpu::RenderPipeline; 2],
    copy_pipeline: wgpu::RenderPipeline,
    globals_layout: wgpu::BindGroupLayout,
    copy_layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    meshes: Vec<GpuMesh>,
    views: HashMap<u64, Targets>,
    frame: u64,
}

/// The uniform block, as `Globals` in the shader.
fn globals_bytes(frame: &Frame3d) -> Vec<u8> {
    let mut floats: Vec<f32> = frame.clip_from_world.to_cols_array().to_vec();
    floats.extend_from_slice(&[frame.eye_mm.x, frame.eye_mm.y, frame.eye_mm.z, 1.0]);
    floats.extend_from_slice(&[frame.light.x, frame.light.y, frame.light.z, 0.0]);
    bytemuck::cast_slice(&floats).to_vec()
}

const GLOBALS_SIZE: u64 = (16 + 4 + 4) * 4;

fn linear_from_srgb(c: f32) -> f64 {
    let c = f64::from(c);
    if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
}

impl Renderer3d {
    /// Pipelines for a pass whose target has `target_format`.
    pub fn new(device: &wgpu::Device, target_format: wgpu::TextureFormat) -> Renderer3d {
        let module = device.create_shader_module(wgpu::include_wgsl!("view3d.wgsl"));
        let globals_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("view3d globals"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(GLOBALS_SIZE),
                },
                count: None,
            }],
        });
        let copy_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("view3d copy"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: true },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let mesh_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("view3d meshes"),
            bind_group_layouts: &[Some(&globals_layout)],
            immediate_size: 0,
        });
        let mesh_pipeline = |samples| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("view3d meshes"),
                layout: Some(&mesh_layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_mesh"),
                    buffers: &[
                        Some(wgpu::VertexBufferLayout {
                            array_stride: 12,
                            step_mode: wgpu::VertexStepMode::Vertex,
                            attributes: &wgpu::vertex_attr_array![0 => Float32x3],
                        }),
                        // One colour per draw, as an instance attribute.
                        Some(wgpu::VertexBufferLayout {
                            array_stride: 16,
                            step_mode: wgpu::VertexStepMode::Instance,
                            attributes: &wgpu::vertex_attr_array![1 => Float32x4],
                        }),
                    ],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState { cull_mode: None, ..Default::default() },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(wgpu::CompareFunction::Less),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState { count: samples, ..Default::default() },
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_mesh"),
                    targets: &[Some(PICTURE_FORMAT.into())],
                    compilation_options: Default::default(),
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let copy_pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("view3d copy"),
            bind_group_layouts: &[Some(&copy_layout)],
            immediate_size: 0,
        });
        let copy_pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("view3d copy"),
            layout: Some(&copy_pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_blit"),
                buffers: &[],
                compilation_options: Default::default(),
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState { count: EGUI_PASS_SAMPLES, ..Default::default() },
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some(if target_format.is_srgb() { "fs_blit_linear" } else { "fs_blit_gamma" }),
                targets: &[Some(target_format.into())],
                compilation_options: Default::default(),
            }),
            multiview_mask: None,
            cache: None,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("view3d picture"),
            mag_filter: wgpu::FilterMode::Nearest,
            min_filter: wgpu::FilterMode::Nearest,
            ..Default::default()
        });
        Renderer3d {
            target_format,
            mesh_pipelines: [mesh_pipeline(1), mesh_pipeline(MSAA_SAMPLES)],
            copy_pipeline,
            globals_layout,
            copy_layout,
            sampler,
            meshes: Vec::new(),
            views: HashMap::new(),
            frame: 0,
        }
    }

    fn targets(&self, device: &wgpu::Device, size_px: [u32; 2]) -> Targets {
        let size = wgpu::Extent3d { width: size_px[0], height: size_px[1], depth_or_array_layers: 1 };
        let texture = |label, format, samples, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size,
                mip_level_count: 1,
                sample_count: samples,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let attachment = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let color_msaa = texture("view3d colour", PICTURE_FORMAT, MSAA_SAMPLES, attachment);
        let depth_msaa = texture("view3d depth", DEPTH_FORMAT, MSAA_SAMPLES, attachment);
        let depth = texture("view3d depth", DEPTH_FORMAT, 1, attachment);
        let picture_usage = attachment | wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC;
        let picture_texture = texture("view3d picture", PICTURE_FORMAT, 1, picture_usage);
        let picture = picture_texture.create_view(&Default::default());
        let copy_bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("view3d copy"),
            layout: &self.copy_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&picture) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&self.sampler) },
            ],
        });
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("view3d globals"),
            size: GLOBALS_SIZE,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let globals_bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("view3d globals"),
            layout: &self.globals_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: globals.as_entire_binding() }],
        });
        let (colors, colors_capacity) = color_buffer(device, 8);
        Targets {
            size_px,
            color_msaa: color_msaa.create_view(&Default::default()),
            depth_msaa: depth_msaa.create_view(&Default::default()),
            depth: depth.create_view(&Default::default()),
            picture,
            picture_texture,
            copy_bind,
            globals,
            globals_bind,
            colors,
            colors_capacity,
        }
    }

    /// The uploaded copy of `mesh`, uploading it the first time.
    fn upload(&mut self, device: &wgpu::Device, mesh: &Arc<ViewMesh>) -> usize {
        if let Some(i) = self.meshes.iter().position(|m| Arc::ptr_eq(&m.source, mesh)) {
            self.meshes[i].last_frame = self.frame;
            return i;
        }
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("view3d vertices"),
            contents: bytemuck::cast_slice(&mesh.positions),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("view3d indices"),
            contents: bytemuck::cast_slice(&mesh.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        self.meshes.push(GpuMesh { source: mesh.clone(), vertices, indices, last_frame: self.frame });
        self.meshes.len() - 1
    }

    /// Draws `frame` into its view's offscreen picture.
    pub fn render(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        frame: &Frame3d,
    ) {
        self.frame += 1;
        let size_px = [frame.size_px[0].max(1), frame.size_px[1].max(1)];
        if self.views.get(&frame.view_id).is_none_or(|t| t.size_px != size_px) {
            let targets = self.targets(device, size_px);
            self.views.insert(frame.view_id, targets);
        }
        // Empty meshes are skipped: a zero-sized buffer cannot be bound.
        let visible: Vec<&Draw> = frame.draws.iter().filter(|d| !d.mesh.indices.is_empty()).collect();
        let drawn: Vec<usize> = visible.iter().map(|d| self.upload(device, &d.mesh)).collect();
        let now = self.frame;
        let Some(targets) = self.views.get_mut(&frame.view_id) else { return };
        queue.write_buffer(&targets.globals, 0, &globals_bytes(frame));
        if targets.colors_capacity < visible.len() {
            (targets.colors, targets.colors_capacity) = color_buffer(device, visible.len());
        }
        let colors: Vec<f32> = visible.iter().flat_map(|d| d.rgba).collect();
        if !colors.is_empty() {
            queue.write_buffer(&targets.colors, 0, bytemuck::cast_slice(&colors));
        }
        let [r, g, b, a] = frame.background;
        let clear =
            wgpu::Color { r: linear_from_srgb(r), g: linear_from_srgb(g), b: linear_from_srgb(b), a: f64::from(a) };
        let (color, resolve, depth, pipeline) = if frame.antialias {
            (&targets.color_msaa, Some(&targets.picture), &targets.depth_msaa, &self.mesh_pipelines[1])
        } else {
            (&targets.picture, None, &targets.depth, &self.mesh_pipelines[0])
        };
        // The multisampled colour is only needed until it is resolved.
        let store = if resolve.is_some() { wgpu::StoreOp::Discard } else { wgpu::StoreOp::Store };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("view3d"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: color,
                depth_slice: None,
                resolve_target: resolve,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(clear), store },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: depth,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &targets.globals_bind, &[]);
        pass.set_vertex_buffer(1, targets.colors.slice(..));
        for (k, &i) in drawn.iter().enumerate() {
            let mesh = &self.meshes[i];
            pass.set_vertex_buffer(0, mesh.vertices.slice(..));
            pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..mesh.source.indices.len() as u32, 0, k as u32..k as u32 + 1);
        }
        drop(pass);
        self.meshes.retain(|m| now - m.last_frame < FORGET_AFTER_FRAMES);
    }

    /// Copies a view's picture into egui's pass (its viewport is the view's rectangle).
    pub fn copy_into(&self, pass: &mut wgpu::RenderPass<'static>, view_id: u64) {
        let Some(targets) = self.views.get(&view_id) else { return };
        pass.set_pipeline(&self.copy_pipeline);
        pass.set_bind_group(0, &targets.copy_bind, &[]);
        pass.draw(0..3, 0..1);
    }

    /// The picture of a view, for measuring and for tests: its texture.
    pub fn picture(&self, view_id: u64) -> Option<&wgpu::Texture> {
        self.views.get(&view_id).map(|t| &t.picture_texture)
    }

    /// How many meshes are uploaded.
    pub fn uploaded_meshes(&self) -> usize {
        self.meshes.len()
    }
}

fn color_buffer(device: &wgpu::Device, draws: usize) -> (wgpu::Buffer, usize) {
    let capacity = draws.next_power_of_two().max(8);
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("view3d colours"),
        size: (capacity * 16) as u64,
        usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    (buffer, capacity)
}
