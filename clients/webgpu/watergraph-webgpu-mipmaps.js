// A mipmapped node texture in WebGPU, which makes no mipmaps of its own: the full chain
// (as the GL runtime's glFullChainLevels) and each level drawn from the one above. Used by the
// runner (watergraph-webgpu.js) and the probe (watergraph-webgpu-probe.js).

// The number of levels down to 1x1.
export function fullChainLevels(width, height) {
  let levels = 1;
  for (let side = Math.max(width, height); side > 1; side = Math.floor(side / 2)) ++levels;
  return levels;
}

// Each level below the first from the one above, as the GL runtime's glGenerateMipmap (WebGPU
// has no mipmap generation of its own): a bilinear sample at each texel's centre, which for
// even sizes is the box average of the 2x2 texels above it; an sRGB format decodes on the
// read and encodes on the write, so the average is of linear values, as Mesa's.
export function generateMipmaps(device, tex, format, levels) {
  const module = device.createShaderModule({ label: 'node texture mipmaps', code: `
@group(0) @binding(0) var wg_level: texture_2d<f32>;
@group(0) @binding(1) var wg_level_sampler: sampler;
@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
  return vec4<f32>(select(-1.0, 3.0, i == 1u), select(-1.0, 3.0, i == 2u), 0.0, 1.0);
}
@fragment fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
  return textureSampleLevel(wg_level, wg_level_sampler, p.xy / vec2<f32>(max(textureDimensions(wg_level) / 2u, vec2<u32>(1u))), 0.0);
}
` });
  const pipeline = device.createRenderPipeline({ layout: 'auto', vertex: { module, entryPoint: 'vs' },
    fragment: { module, entryPoint: 'fs', targets: [{ format }] }, primitive: { topology: 'triangle-list' } });
  const sampler = device.createSampler({ magFilter: 'linear', minFilter: 'linear', addressModeU: 'clamp-to-edge', addressModeV: 'clamp-to-edge' });
  const encoder = device.createCommandEncoder();
  for (let level = 1; level < levels; ++level) {
    const group = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries: [
      { binding: 0, resource: tex.createView({ baseMipLevel: level - 1, mipLevelCount: 1 }) }, { binding: 1, resource: sampler }] });
    const pass = encoder.beginRenderPass({ colorAttachments: [{ view: tex.createView({ baseMipLevel: level, mipLevelCount: 1 }),
      loadOp: 'clear', clearValue: [0, 0, 0, 0], storeOp: 'store' }] });
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    pass.draw(3);
    pass.end();
  }
  device.queue.submit([encoder.finish()]);
}
