// Prints what cli_test.sh checks of a .glb or .gltf that `lsys export` wrote,
// on one line: vertices=V nodes=N joints=J skins=S height=H. V: POSITION
// counts of every mesh primitive, each mesh once; J: nodes named joint_<i>;
// H: the scene's extent in y (0 when empty), every vertex
// placed by its nodes' transforms from the default scene's roots down
// (glTF 2.0 §3.5.3: translation, rotation, scale, or a column-major matrix).
// Usage: node gltf_summary.mjs FILE
import { readFileSync } from 'node:fs';

const file = process.argv[2];
const bytes = readFileSync(file);
let gltf, bin;
if (bytes.readUInt32LE(0) === 0x46546c67) { // "glTF": JSON chunk, then the BIN chunk (§4.4)
  const jsonLength = bytes.readUInt32LE(12);
  gltf = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString('utf8'));
  const binStart = 20 + jsonLength;
  if (binStart < bytes.length) bin = bytes.subarray(binStart + 8, binStart + 8 + bytes.readUInt32LE(binStart));
} else {
  gltf = JSON.parse(bytes.toString('utf8'));
  const uri = gltf.buffers?.[0]?.uri;
  if (uri) bin = Buffer.from(uri.slice(uri.indexOf(',') + 1), 'base64');
}

// 4x4 column-major matrices.
const multiply = (a, b) => {
  const m = new Array(16).fill(0);
  for (let c = 0; c < 4; ++c)
    for (let r = 0; r < 4; ++r)
      for (let k = 0; k < 4; ++k) m[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return m;
};
const localMatrix = (node) => {
  if (node.matrix) return node.matrix;
  const [x, y, z, w] = node.rotation ?? [0, 0, 0, 1];
  const [sx, sy, sz] = node.scale ?? [1, 1, 1];
  const [tx, ty, tz] = node.translation ?? [0, 0, 0];
  return [
    (1 - 2 * (y * y + z * z)) * sx, 2 * (x * y + z * w) * sx, 2 * (x * z - y * w) * sx, 0,
    2 * (x * y - z * w) * sy, (1 - 2 * (x * x + z * z)) * sy, 2 * (y * z + x * w) * sy, 0,
    2 * (x * z + y * w) * sz, 2 * (y * z - x * w) * sz, (1 - 2 * (x * x + y * y)) * sz, 0,
    tx, ty, tz, 1,
  ];
};

const positionsOf = (accessorIndex) => {
  const accessor = gltf.accessors[accessorIndex];
  const view = gltf.bufferViews[accessor.bufferView];
  const stride = view.byteStride ?? 12;
  const start = (view.byteOffset ?? 0) + (accessor.byteOffset ?? 0);
  const points = [];
  for (let i = 0; i < accessor.count; ++i) {
    const at = start + i * stride;
    points.push([bin.readFloatLE(at), bin.readFloatLE(at + 4), bin.readFloatLE(at + 8)]);
  }
  return points;
};

let yMin = Infinity, yMax = -Infinity;
const visit = (index, parent) => {
  const node = gltf.nodes[index];
  const world = multiply(parent, localMatrix(node));
  if (node.mesh !== undefined)
    for (const primitive of gltf.meshes[node.mesh].primitives)
      for (const [x, y, z] of positionsOf(primitive.attributes.POSITION)) {
        const placed = world[1] * x + world[5] * y + world[9] * z + world[13];
        yMin = Math.min(yMin, placed);
        yMax = Math.max(yMax, placed);
      }
  for (const child of node.children ?? []) visit(child, world);
};
const identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
for (const root of gltf.scenes[gltf.scene ?? 0].nodes) visit(root, identity);

const nodes = gltf.nodes ?? [];
const vertices = (gltf.meshes ?? []).reduce(
  (sum, mesh) => sum + mesh.primitives.reduce((s, p) => s + gltf.accessors[p.attributes.POSITION].count, 0), 0);
const joints = nodes.filter((n) => /^joint_/.test(n.name ?? '')).length;
const height = yMax >= yMin ? yMax - yMin : 0;
console.log(`vertices=${vertices} nodes=${nodes.length} joints=${joints} skins=${(gltf.skins ?? []).length} ` +
            `height=${height.toFixed(6)}`);
