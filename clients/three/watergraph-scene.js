// The runtime's built-in scene (sky, pool floor, shore, pillars, rocks) in three.js, built
// from the description `watergraph scene` writes: its mesh, sun and the runtime's own
// ES 3.00 shaders, so it is drawn as `watergraph render` draws it.
import * as THREE from 'three';
import { checkSceneDescription, createSky, runtimeMaterial, objectClipPlane, WaterGraphError } from './watergraph-passes.js';

// Loads a scene description (JSON) from `url`.
export async function loadSceneDescription(url) {
  let response;
  try {
    response = await fetch(url);
  } catch (e) {
    throw new WaterGraphError(`cannot load the scene description from ${url}: ${e.message}`);
  }
  if (!response.ok) throw new WaterGraphError(`cannot load the scene description from ${url}: HTTP ${response.status}`);
  return checkSceneDescription(await response.json());
}

// The opaque scene mesh with the runtime's lit shader. Its clip plane is the renderer's
// first clipping plane (the passes set it for reflection and refraction), in the mesh's
// own space, as the runtime's u_clip_plane. `m`: another mesh of the description's layout
// (its attributes, vertices and indices) drawn the same way.
export function createOpaqueScene(description, sunDirection, m = description.mesh) {
  const stride = m.attributes.reduce((n, a) => n + a.components, 0);
  if (m.vertices.length % stride !== 0) throw new WaterGraphError('the scene description\'s mesh vertices do not fill whole vertices');
  const interleaved = new THREE.InterleavedBuffer(new Float32Array(m.vertices), stride);
  const geometry = new THREE.BufferGeometry();
  let offset = 0;
  for (const a of m.attributes) {
    geometry.setAttribute(a.name, new THREE.InterleavedBufferAttribute(interleaved, a.components, offset));
    offset += a.components;
  }
  geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(m.indices), 1));
  // Positions are not in "position", which three.js bounds by: the mesh is never culled,
  // and this sphere only orders it among opaque objects.
  geometry.boundingSphere = new THREE.Sphere(new THREE.Vector3(), 60);
  const uniforms = {
    u_view_projection: { value: new THREE.Matrix4() },
    u_clip_plane: { value: new THREE.Vector4(0, 0, 0, 1) },
    u_sun_direction: { value: sunDirection },
  };
  const mesh = new THREE.Mesh(geometry, runtimeMaterial(description, 'opaque_vertex', 'opaque_fragment', uniforms));
  mesh.name = 'watergraph opaque scene';
  mesh.frustumCulled = false;
  mesh.onBeforeRender = (renderer, scene, camera) => {
    // The shader has no model matrix: the world matrix goes into the view-projection.
    uniforms.u_view_projection.value.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse).multiply(mesh.matrixWorld);
    objectClipPlane(renderer, mesh, uniforms.u_clip_plane.value);
    mesh.material.uniformsNeedUpdate = true;
  };
  return mesh;
}

// The whole built-in scene as one group (add it to your scene): the opaque mesh and the
// sky. group.userData.sunDirection is the sun both read; set it to move the sun.
export function createBuiltinScene(description) {
  checkSceneDescription(description);
  const sun = new THREE.Vector3().fromArray(description.sun_direction);
  const group = new THREE.Group();
  group.name = 'watergraph built-in scene';
  group.add(createOpaqueScene(description, sun), createSky(description, sun));
  group.userData.sunDirection = sun;
  return group;
}

// The description's floating buoys (`watergraph render --buoys`, the editor's "buoys"):
// one mesh per rest point, lit by the runtime's opaque shader. Each frame, place(i,
// position, up) puts buoy i where a surface query (`compile --target query-js`) says the
// water moves its rest point, tilted to the normal there; its vertices are rotated on the
// CPU as the runtime rotates them (the shader has no normal matrix). Add `group` to your
// scene; `restPoints` are the (x0, z0) to query.
export function createFloatingBuoys(description, sunDirection) {
  const b = description.buoys;
  if (!b || !Array.isArray(b.rest_points)) throw new WaterGraphError('the scene description has no "buoys" (write it with a newer `watergraph scene`)');
  const attributes = description.mesh.attributes;
  const stride = attributes.reduce((n, a) => n + a.components, 0);
  const local = new Float32Array(b.vertices);
  const group = new THREE.Group();
  group.name = 'watergraph floating buoys';
  const meshes = b.rest_points.map(() => {
    const mesh = createOpaqueScene(description, sunDirection, { attributes, vertices: local, indices: b.indices });
    mesh.name = 'watergraph buoy';
    group.add(mesh);
    return mesh;
  });
  const up = new THREE.Vector3(), forward = new THREE.Vector3(), right = new THREE.Vector3();
  const p = new THREE.Vector3(), n = new THREE.Vector3();
  function place(i, position, normal) {
    // The runtime's axes (runtime/floating_buoys.cpp): up, and x and z turned with it.
    up.fromArray(normal).normalize();
    if (!(up.lengthSq() > 0)) up.set(0, 1, 0);
    if (up.y < 0) up.negate();
    forward.set(1, 0, 0).cross(up);
    if (forward.length() > 1e-6) forward.normalize(); else forward.set(0, 0, 1);
    right.copy(up).cross(forward);
    const buffer = meshes[i].geometry.getAttribute(attributes[0].name).data;
    const out = buffer.array;
    for (let v = 0; v < local.length; v += stride) {
      p.set(local[v], local[v + 1], local[v + 2]);
      n.set(local[v + 3], local[v + 4], local[v + 5]);
      out[v] = position[0] + right.x * p.x + up.x * p.y + forward.x * p.z;
      out[v + 1] = position[1] + right.y * p.x + up.y * p.y + forward.y * p.z;
      out[v + 2] = position[2] + right.z * p.x + up.z * p.y + forward.z * p.z;
      out[v + 3] = right.x * n.x + up.x * n.y + forward.x * n.z;
      out[v + 4] = right.y * n.x + up.y * n.y + forward.y * n.z;
      out[v + 5] = right.z * n.x + up.z * n.y + forward.z * n.z;
    }
    buffer.needsUpdate = true;
  }
  return { group, restPoints: b.rest_points, place };
}

// A camera preset of the description ("above", "grazing", "underwater", "topdown") as a
// THREE.PerspectiveCamera for `aspect`.
export function presetCamera(description, name, aspect) {
  const cameras = description.cameras;
  const c = cameras && Object.prototype.hasOwnProperty.call(cameras, name) ? cameras[name] : undefined;  // not "__proto__"
  if (!c) throw new WaterGraphError(`the scene description has no camera '${name}'`);
  const camera = new THREE.PerspectiveCamera(c.fov_y_degrees, aspect, c.near, c.far);
  camera.position.fromArray(c.position);
  camera.up.fromArray(c.up);
  camera.lookAt(new THREE.Vector3().fromArray(c.target));
  camera.updateMatrixWorld();
  return camera;
}
