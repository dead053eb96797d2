// render/scene.js with the real three.js (no WebGL needed to build a scene): struts as instanced
// prisms in blue/yellow/red with 4/3/5-sided sections and their real lengths, balls, highlight,
// faces, and the pixel colour check the e2e tests rely on.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as THREE from 'three';
import { buildScene, COLOURS, BACKGROUND, KIND_COLOUR, SECTION_SIDES } from '../src/render/scene.js';

const PHI = (1 + Math.sqrt(5)) / 2;

/** Five balls: struts B0, Y0, R0, B1 from ball 0, and one that is no Zome vector (kind 255). */
function snapshot({ kinds = [0, 3, 6, 1, 255], scale = 1, translation = [0, 0, 0], triangles = [] } = {}) {
  return {
    version: 1, scale, translation,
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 0.5, 0.5, 0.5, 0, 0.5, PHI / 2, PHI, 0, 0]),
    struts: new Uint32Array([0, 1, 0, 2, 0, 3, 0, 4, 1, 2].slice(0, 2 * kinds.length)),
    kinds: new Uint8Array(kinds), triangles: new Uint32Array(triangles),
  };
}

function makeScene() {
  const scene = buildScene(THREE, new THREE.PerspectiveCamera());
  const meshes = () => {
    const found = {};
    scene.root.traverse((o) => {
      if (!o.isInstancedMesh) return;
      const p = o.geometry.parameters;
      const name = o.geometry.type === 'SphereGeometry' ? 'balls'
        : Object.keys(SECTION_SIDES).find((c) => SECTION_SIDES[c] === p.radialSegments);
      found[name] = o;
    });
    return found;
  };
  return { scene, meshes };
}

const colourAt = (mesh, i) => { const c = new THREE.Color(); mesh.getColorAt(i, c); return c.getHex(); };
function transformAt(mesh, i) {
  const m = new THREE.Matrix4(), position = new THREE.Vector3(), q = new THREE.Quaternion(), scale = new THREE.Vector3();
  mesh.getMatrixAt(i, m);
  m.decompose(position, q, scale);
  return { position, scale, axis: new THREE.Vector3(0, 1, 0).applyQuaternion(q) };
}

test('kind → colour: B0..B2 blue, Y0..Y2 yellow, R0..R2 red; sections 4, 3 and 5 sided', () => {
  assert.deepEqual(KIND_COLOUR, ['blue', 'blue', 'blue', 'yellow', 'yellow', 'yellow', 'red', 'red', 'red']);
  assert.deepEqual(SECTION_SIDES, { blue: 4, yellow: 3, red: 5 });
  assert.equal(KIND_COLOUR[255], undefined);
});

test('colours are Zome blue, yellow and red (each channel dominated as the pixel check expects)', () => {
  const rgb = (hex) => [hex >> 16, (hex >> 8) & 255, hex & 255];
  const [br, bg, bb] = rgb(COLOURS.blue), [yr, yg, yb] = rgb(COLOURS.yellow), [rr, rg, rb] = rgb(COLOURS.red);
  assert.ok(bb > br && bb > bg, 'blue is mostly blue');
  assert.ok(yr > yb * 4 && yg > yb * 4, 'yellow is red + green');
  assert.ok(rr > rg * 3 && rr > rb * 3, 'red is mostly red');
});

test('each strut is an instance in its colour mesh; a non-Zome strut is not drawn', () => {
  const { scene, meshes } = makeScene();
  scene.setModel(snapshot());
  const m = meshes();
  assert.deepEqual([m.blue.count, m.yellow.count, m.red.count, m.balls.count], [2, 1, 1, 5]);
  assert.equal(colourAt(m.blue, 0), COLOURS.blue);
  assert.equal(colourAt(m.yellow, 0), COLOURS.yellow);
  assert.equal(colourAt(m.red, 0), COLOURS.red);
});

test('an instance spans its strut: centred between its balls, along it, as long as it', () => {
  const { scene, meshes } = makeScene();
  scene.setModel(snapshot());
  const { red, blue } = meshes();
  const r0 = transformAt(red, 0);
  assert.ok(Math.abs(r0.scale.y - Math.sqrt(2 + PHI) / 2) < 1e-6, `R0 length ${r0.scale.y}`);
  assert.ok(r0.position.distanceTo(new THREE.Vector3(0, 0.25, PHI / 4)) < 1e-6);
  assert.ok(r0.axis.distanceTo(new THREE.Vector3(0, 1, PHI).normalize()) < 1e-6);
  assert.ok(Math.abs(transformAt(blue, 1).scale.y - PHI) < 1e-6); // the B1 strut
  assert.ok(Math.abs(r0.scale.x - 1) < 1e-6); // thickness is not stretched
});

test('the model transform (Zome units → mesh units) is applied to the whole model', () => {
  const { scene, meshes } = makeScene();
  scene.setModel(snapshot({ scale: 0.25, translation: [1, 2, 3] }));
  const group = meshes().blue.parent;
  assert.equal(group.scale.x, 0.25);
  assert.deepEqual(group.position.toArray(), [1, 2, 3]);
  assert.equal(meshes().balls.parent, group);
});

test('highlight: chosen kinds glow, the rest dim; null restores; it survives a new snapshot', () => {
  const { scene, meshes } = makeScene();
  scene.setModel(snapshot());
  scene.highlightKinds([3]);
  let m = meshes();
  assert.equal(colourAt(m.yellow, 0), COLOURS.highlight);
  assert.equal(colourAt(m.blue, 0), 0x555a63);
  scene.setModel(snapshot()); // a run sends new models while the user hovers a row
  m = meshes();
  assert.equal(colourAt(m.yellow, 0), COLOURS.highlight);
  scene.highlightKinds(null);
  assert.equal(colourAt(m.yellow, 0), COLOURS.yellow);
  assert.equal(colourAt(m.blue, 1), COLOURS.blue);
});

test('meshes are reused between snapshots; a colour with no struts is hidden', () => {
  const { scene, meshes } = makeScene();
  scene.setModel(snapshot());
  const before = meshes();
  scene.setModel(snapshot({ kinds: [0, 3] }));
  const after = meshes();
  assert.equal(after.blue, before.blue);
  assert.equal(after.blue.count, 1);
  assert.equal(after.red.visible, false);
});

test('faces are a separate mesh, hidden until shown', () => {
  const { scene } = makeScene();
  scene.setModel(snapshot({ triangles: [0, 1, 2] }));
  const faces = [];
  scene.root.traverse((o) => { if (o.isMesh && !o.isInstancedMesh) faces.push(o); });
  assert.equal(faces.length, 1);
  assert.equal(faces[0].visible, false);
  scene.setVisibility(true, false);
  assert.equal(faces[0].visible, true);
});

test('colourCoverage: strut colours, shaded ones too, the highlight and the background are told apart', () => {
  const { scene } = makeScene();
  const shade = (hex, f) => [(hex >> 16) * f, ((hex >> 8) & 255) * f, (hex & 255) * f, 255].map(Math.round);
  const pixels = new Uint8Array([
    ...shade(COLOURS.blue, 1), ...shade(COLOURS.blue, 0.6),
    ...shade(COLOURS.yellow, 1), ...shade(COLOURS.red, 0.8), ...shade(COLOURS.highlight, 1),
    ...BACKGROUND, 255, ...BACKGROUND, 255, ...shade(COLOURS.ball, 1),
  ]);
  assert.deepEqual(scene.colourCoverage(pixels), { blue: 2 / 8, yellow: 1 / 8, red: 1 / 8, highlight: 1 / 8, background: 2 / 8 });
});

test('the render worker clears to BACKGROUND (colourCoverage counts background by exact match)', () => {
  const source = readFileSync(new URL('../src/render/render_worker.js', import.meta.url), 'utf8');
  const clear = Number(source.match(/setClearColor\((0x[0-9a-f]+)\)/i)[1]);
  assert.deepEqual([clear >> 16, (clear >> 8) & 255, clear & 255], BACKGROUND);
});
