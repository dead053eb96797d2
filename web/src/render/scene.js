// The model as three.js objects: struts as instanced prisms in Zome blue/yellow/red (real lengths;
// blue struts have a rectangular, yellow a triangular, red a pentagonal section, as the real
// parts), white balls, optional faces, translucent input surface and mirror plane. Runs in the render worker;
// THREE is passed in so this file has no import to resolve.

// Sizes in Zome units (b0 = 46.27 mm centre to centre): ball 17.67 mm across, struts ~7 mm thick.
export const BALL_RADIUS = 17.673 / 2 / 46.27;
const STRUT_RADIUS = 3.6 / 46.27;
export const COLOURS = { blue: 0x1f5fd6, yellow: 0xf2c20f, red: 0xd42a1e, ball: 0xf4f4f4, highlight: 0x20e070 };
export const BACKGROUND = [0x20, 0x24, 0x2b];
export const KIND_COLOUR = ['blue', 'blue', 'blue', 'yellow', 'yellow', 'yellow', 'red', 'red', 'red'];
export const SECTION_SIDES = { blue: 4, yellow: 3, red: 5 };

export function buildScene(THREE, camera) {
  const root = new THREE.Scene();
  root.add(new THREE.HemisphereLight(0xffffff, 0x404050, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(3, 5, 4);
  camera.add(sun);
  root.add(camera);
  const modelGroup = new THREE.Group(); // Zome units → mesh units (the model's transform)
  root.add(modelGroup);

  // Geometries and materials live as long as the scene (one shader program each): re-creating
  // them per snapshot would recompile shaders.
  const shared = {
    ball: { geometry: new THREE.SphereGeometry(BALL_RADIUS, 14, 10),
      material: new THREE.MeshStandardMaterial({ color: COLOURS.ball, roughness: 0.35 }) },
    faces: new THREE.MeshStandardMaterial({ color: 0x9aa7b8, transparent: true, opacity: 0.45,
      side: THREE.DoubleSide, depthWrite: false }),
    surface: new THREE.MeshStandardMaterial({ color: 0xe8d9c0, transparent: true, opacity: 0.3,
      depthWrite: false, side: THREE.DoubleSide }),
    mirror: new THREE.MeshBasicMaterial({ color: 0xa8c8ff, transparent: true, opacity: 0.16, depthWrite: false,
      side: THREE.DoubleSide }),
  };
  for (const colour of ['blue', 'yellow', 'red']) {
    shared[colour] = {
      geometry: new THREE.CylinderGeometry(STRUT_RADIUS, STRUT_RADIUS, 1, SECTION_SIDES[colour], 1),
      material: new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.45, metalness: 0.05 }),
    };
  }

  const pool = {}; // instanced meshes kept and grown between snapshots
  let struts = {}; // colour → {mesh, ids, base}
  let kinds = new Uint8Array(0);
  let highlighted = null;
  let buildStep = null; // {strutStep, ballStep, step}: the Build view's colouring, or null
  let ballPositions = new Float32Array(0);
  let facesMesh = null;
  let surfaceMesh = null;
  let showFaces = false;
  let showSurface = false;
  let mirrorPlane = null; // {axis, at} (Zome units) of a symmetric model, drawn as a translucent sheet
  let mirrorMesh = null;
  let showMirror = true;

  function pooledMesh(key, geometry, material, count) {
    let mesh = pool[key];
    if (!mesh || mesh.instanceMatrix.count < count) {
      if (mesh) {
        modelGroup.remove(mesh);
        mesh.dispose();
      }
      mesh = new THREE.InstancedMesh(geometry, material, Math.max(16, Math.ceil(count * 1.5)));
      mesh.frustumCulled = false;
      pool[key] = mesh;
      modelGroup.add(mesh);
    }
    mesh.count = count;
    mesh.visible = count > 0;
    return mesh;
  }

  function highlightKinds(kindIds) {
    highlighted = kindIds;
    const dim = new THREE.Color(0x555a63), glow = new THREE.Color(COLOURS.highlight);
    for (const { mesh, ids, base } of Object.values(struts)) {
      ids.forEach((strut, k) => mesh.setColorAt(k, !kindIds ? base : kindIds.includes(kinds[strut]) ? glow : dim));
      if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
    }
  }

  /**
   * The Build view: struts of earlier steps in their colours, this step's glowing, later ones
   * faint; later balls hidden. `state` is {strutStep: Int32Array, ballStep: Int32Array, step} or null.
   */
  function setBuildStep(state) {
    buildStep = state;
    const faint = new THREE.Color(0x2e333b), glow = new THREE.Color(COLOURS.highlight);
    for (const { mesh, ids, base } of Object.values(struts)) {
      ids.forEach((strut, k) => {
        const t = state ? state.strutStep[strut] : -1;
        mesh.setColorAt(k, !state ? base : t === state.step ? glow : t < state.step ? base : faint);
      });
      if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
    }
    const balls = pool.balls;
    if (!balls) return;
    const m = new THREE.Matrix4(), p = new THREE.Vector3();
    const count = ballPositions.length / 3;
    for (let i = 0; i < count && i < balls.count; i++) {
      const shown = !state || state.ballStep[i] <= state.step;
      m.makeTranslation(p.fromArray(ballPositions, 3 * i));
      if (!shown) m.scale(p.set(0, 0, 0));
      balls.setMatrixAt(i, m);
    }
    balls.instanceMatrix.needsUpdate = true;
    if (!state && highlighted) highlightKinds(highlighted);
  }

  function setModel(snapshot) {
    const { positions, triangles } = snapshot;
    kinds = snapshot.kinds;
    modelGroup.scale.setScalar(snapshot.scale);
    modelGroup.position.fromArray(snapshot.translation);
    const byColour = { blue: [], yellow: [], red: [] };
    for (let i = 0; i < kinds.length; i++) {
      const colour = KIND_COLOUR[kinds[i]];
      if (colour) byColour[colour].push(i);
    }
    const a = new THREE.Vector3(), b = new THREE.Vector3(), dir = new THREE.Vector3();
    const up = new THREE.Vector3(0, 1, 0), q = new THREE.Quaternion(), s = new THREE.Vector3();
    const m = new THREE.Matrix4();
    struts = {};
    for (const [colour, ids] of Object.entries(byColour)) {
      const mesh = pooledMesh(colour, shared[colour].geometry, shared[colour].material, ids.length);
      const base = new THREE.Color(COLOURS[colour]);
      ids.forEach((strut, k) => {
        a.fromArray(positions, 3 * snapshot.struts[2 * strut]);
        b.fromArray(positions, 3 * snapshot.struts[2 * strut + 1]);
        dir.subVectors(b, a);
        const length = dir.length();
        q.setFromUnitVectors(up, dir.normalize());
        s.set(1, length, 1);
        m.compose(a.add(b).multiplyScalar(0.5), q, s);
        mesh.setMatrixAt(k, m);
        mesh.setColorAt(k, base);
      });
      mesh.instanceMatrix.needsUpdate = true;
      if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
      struts[colour] = { mesh, ids, base };
    }
    const nodeCount = positions.length / 3;
    const balls = pooledMesh('balls', shared.ball.geometry, shared.ball.material, nodeCount);
    const p = new THREE.Vector3();
    for (let i = 0; i < nodeCount; i++) balls.setMatrixAt(i, m.makeTranslation(p.fromArray(positions, 3 * i)));
    balls.instanceMatrix.needsUpdate = true;

    if (facesMesh) {
      modelGroup.remove(facesMesh);
      facesMesh.geometry.dispose();
      facesMesh = null;
    }
    if (triangles.length) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
      geometry.computeVertexNormals();
      facesMesh = new THREE.Mesh(geometry, shared.faces);
      facesMesh.visible = showFaces;
      modelGroup.add(facesMesh);
    }
    ballPositions = positions;
    fitMirrorPlane();
    buildStep = null; // a new model has other steps; the Build view sends them again
    if (highlighted) highlightKinds(highlighted);
  }

  /**
   * The mirror plane of a symmetric model: a translucent sheet across `axis` at `at` (Zome units, the
   * model's own coordinates), one ball beyond the model's extent on the two other axes. null removes it.
   */
  function setMirrorPlane(plane) {
    mirrorPlane = plane;
    fitMirrorPlane();
  }

  function fitMirrorPlane() {
    if (mirrorMesh) {
      modelGroup.remove(mirrorMesh);
      mirrorMesh.geometry.dispose();
      mirrorMesh = null;
    }
    if (!mirrorPlane || ballPositions.length < 3) return;
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < ballPositions.length; i++) {
      lo[i % 3] = Math.min(lo[i % 3], ballPositions[i]);
      hi[i % 3] = Math.max(hi[i % 3], ballPositions[i]);
    }
    const margin = 4 * BALL_RADIUS;
    const [u, v] = [0, 1, 2].filter((k) => k !== mirrorPlane.axis);
    const corners = [[lo[u] - margin, lo[v] - margin], [hi[u] + margin, lo[v] - margin],
      [hi[u] + margin, hi[v] + margin], [lo[u] - margin, hi[v] + margin]];
    const positions = new Float32Array(12);
    corners.forEach(([a, b], k) => {
      positions[3 * k + mirrorPlane.axis] = mirrorPlane.at;
      positions[3 * k + u] = a;
      positions[3 * k + v] = b;
    });
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setIndex([0, 1, 2, 0, 2, 3]);
    mirrorMesh = new THREE.Mesh(geometry, shared.mirror);
    mirrorMesh.renderOrder = 1; // after the opaque parts, so they show through it
    mirrorMesh.visible = showMirror;
    modelGroup.add(mirrorMesh);
  }

  function setSurface(surface) {
    if (surfaceMesh) {
      root.remove(surfaceMesh);
      surfaceMesh.geometry.dispose();
      surfaceMesh = null;
    }
    if (!surface) return;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(surface.positions, 3));
    geometry.setIndex(new THREE.BufferAttribute(surface.triangles, 1));
    geometry.computeVertexNormals();
    surfaceMesh = new THREE.Mesh(geometry, shared.surface);
    surfaceMesh.visible = showSurface;
    root.add(surfaceMesh);
  }

  function setVisibility(faces, surface, mirror = showMirror) {
    showFaces = faces;
    showSurface = surface;
    showMirror = mirror;
    if (facesMesh) facesMesh.visible = faces;
    if (surfaceMesh) surfaceMesh.visible = surface;
    if (mirrorMesh) mirrorMesh.visible = mirror;
  }

  /** Fractions of the pixels (RGBA bytes) close to each strut colour and to the background. */
  function colourCoverage(pixels) {
    const count = { blue: 0, yellow: 0, red: 0, highlight: 0, background: 0 };
    for (let i = 0; i < pixels.length; i += 4) {
      const r = pixels[i], g = pixels[i + 1], b = pixels[i + 2];
      if (r === BACKGROUND[0] && g === BACKGROUND[1] && b === BACKGROUND[2]) count.background++;
      else if (g > 110 && g > r * 1.8 && g > b * 1.3) count.highlight++;
      else if (b > 110 && b > r * 1.6 && b > g * 1.2) count.blue++;
      else if (r > 130 && g > 100 && b < r * 0.5 && g > r * 0.55) count.yellow++;
      else if (r > 110 && g < r * 0.45 && b < r * 0.45) count.red++;
    }
    const total = pixels.length / 4;
    return { blue: count.blue / total, yellow: count.yellow / total, red: count.red / total,
      highlight: count.highlight / total, background: count.background / total };
  }

  return { root, setModel, setSurface, setMirrorPlane, setVisibility, highlightKinds, setBuildStep, colourCoverage };
}
