// The three.js viewer: struts as instanced prisms in Zome blue/yellow/red (real lengths; blue
// struts have a rectangular, yellow a triangular, red a pentagonal section, as the real parts),
// white balls, optional faces and translucent input surface; orbit/zoom/pan; fit on load.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

// Sizes in Zome units (b0 = 46.27 mm centre to centre): ball 17.67 mm across, struts ~7 mm thick.
const BALL_RADIUS = 17.673 / 2 / 46.27;
const STRUT_RADIUS = 3.6 / 46.27;
export const COLOURS = { blue: 0x1f5fd6, yellow: 0xf2c20f, red: 0xd42a1e, ball: 0xf4f4f4, highlight: 0x20e070 };
const KIND_COLOUR = ['blue', 'blue', 'blue', 'yellow', 'yellow', 'yellow', 'red', 'red', 'red'];
const SECTION_SIDES = { blue: 4, yellow: 3, red: 5 };

export class Viewer {
  constructor(container) {
    this.container = container;
    // Often drawn by software (SwiftShader) on a busy CPU: no MSAA, and frames only when something
    // changed, so the page's thread is not held up by a GPU process that is short of CPU.
    this.renderer = new THREE.WebGLRenderer({ antialias: false });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.needsRender = true;
    this.renderer.setClearColor(0x20242b);
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = true;
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x404050, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(3, 5, 4);
    this.camera.add(sun);
    this.scene.add(this.camera);

    this.modelGroup = new THREE.Group(); // Zome units → mesh units (the model's transform)
    this.scene.add(this.modelGroup);
    this.surfaceMesh = null;
    this.facesMesh = null;
    this.struts = {}; // colour → {mesh, ids, base}
    this.balls = null;
    this.pool = {}; // instanced meshes kept between snapshots
    // Geometries and materials live as long as the viewer (one shader program each).
    const strutMaterial = () => new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.45, metalness: 0.05 });
    this.shared = { ball: { geometry: new THREE.SphereGeometry(BALL_RADIUS, 14, 10),
      material: new THREE.MeshStandardMaterial({ color: COLOURS.ball, roughness: 0.35 }) },
    faces: new THREE.MeshStandardMaterial({ color: 0x9aa7b8, transparent: true, opacity: 0.45,
      side: THREE.DoubleSide, depthWrite: false }) };
    for (const colour of ['blue', 'yellow', 'red']) {
      this.shared[colour] = { geometry: new THREE.CylinderGeometry(STRUT_RADIUS, STRUT_RADIUS, 1,
        SECTION_SIDES[colour], 1), material: strutMaterial() };
    }
    this.snapshot = null;
    this.showFaces = false;
    this.showSurface = false;
    this.highlighted = null;

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    this.renderer.setAnimationLoop(() => {
      const moved = this.controls.update(); // true while the camera moves (also damping)
      if (moved || this.needsRender) this.render();
    });
  }

  requestRender() {
    this.needsRender = true;
  }

  render() {
    this.needsRender = false;
    this.renderer.render(this.scene, this.camera);
  }

  resize() {
    const { clientWidth: w, clientHeight: h } = this.container;
    if (!w || !h) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  /** An instanced mesh that is kept and grown, so a new snapshot costs buffer uploads only
   * (re-creating materials would recompile shaders, which stalls the page for 100s of ms). */
  pooledMesh(key, geometry, material, count) {
    let mesh = this.pool[key];
    if (!mesh || mesh.instanceMatrix.count < count) {
      if (mesh) {
        this.modelGroup.remove(mesh);
        mesh.dispose();
      }
      mesh = new THREE.InstancedMesh(geometry, material, Math.max(16, Math.ceil(count * 1.5)));
      mesh.frustumCulled = false;
      this.pool[key] = mesh;
      this.modelGroup.add(mesh);
    }
    mesh.count = count;
    mesh.visible = count > 0;
    mesh.boundingBox = null; // recomputed from the live instances when fitting
    mesh.boundingSphere = null;
    return mesh;
  }

  /** Shows a snapshot (protocol.js Snapshot); `fit` frames it. */
  setModel(snapshot, { fit = false } = {}) {
    this.snapshot = snapshot;
    const { positions, struts, kinds, triangles } = snapshot;
    this.modelGroup.scale.setScalar(snapshot.scale);
    this.modelGroup.position.fromArray(snapshot.translation);

    const byColour = { blue: [], yellow: [], red: [] };
    for (let i = 0; i < kinds.length; i++) {
      const colour = KIND_COLOUR[kinds[i]];
      if (colour) byColour[colour].push(i);
    }
    const a = new THREE.Vector3(), b = new THREE.Vector3(), dir = new THREE.Vector3();
    const up = new THREE.Vector3(0, 1, 0), q = new THREE.Quaternion(), s = new THREE.Vector3();
    const m = new THREE.Matrix4();
    this.struts = {};
    for (const [colour, ids] of Object.entries(byColour)) {
      const mesh = this.pooledMesh(colour, this.shared[colour].geometry, this.shared[colour].material, ids.length);
      const base = new THREE.Color(COLOURS[colour]);
      ids.forEach((strut, k) => {
        a.fromArray(positions, 3 * struts[2 * strut]);
        b.fromArray(positions, 3 * struts[2 * strut + 1]);
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
      this.struts[colour] = { mesh, ids, base };
    }

    const nodeCount = positions.length / 3;
    const balls = this.pooledMesh('balls', this.shared.ball.geometry, this.shared.ball.material, nodeCount);
    const p = new THREE.Vector3();
    for (let i = 0; i < nodeCount; i++) balls.setMatrixAt(i, m.makeTranslation(p.fromArray(positions, 3 * i)));
    balls.instanceMatrix.needsUpdate = true;
    this.balls = balls;

    if (this.facesMesh) {
      this.modelGroup.remove(this.facesMesh);
      this.facesMesh.geometry.dispose();
      this.facesMesh = null;
    }
    if (triangles.length) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
      geometry.computeVertexNormals();
      this.facesMesh = new THREE.Mesh(geometry, this.shared.faces);
      this.facesMesh.visible = this.showFaces;
      this.modelGroup.add(this.facesMesh);
    }
    if (this.highlighted) this.highlightKinds(this.highlighted);
    if (fit) this.fit();
    this.requestRender();
  }

  /** The input surface (mesh units), drawn translucent when shown. */
  setSurface(surface) {
    if (this.surfaceMesh) {
      this.scene.remove(this.surfaceMesh);
      this.surfaceMesh.geometry.dispose();
      this.surfaceMesh.material.dispose();
      this.surfaceMesh = null;
    }
    if (!surface) return;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(surface.positions, 3));
    geometry.setIndex(new THREE.BufferAttribute(surface.triangles, 1));
    geometry.computeVertexNormals();
    const material = new THREE.MeshStandardMaterial({
      color: 0xe8d9c0, transparent: true, opacity: 0.3, depthWrite: false, side: THREE.DoubleSide,
    });
    this.surfaceMesh = new THREE.Mesh(geometry, material);
    this.surfaceMesh.visible = this.showSurface;
    this.scene.add(this.surfaceMesh);
    this.requestRender();
  }

  setFacesVisible(on) {
    this.showFaces = on;
    if (this.facesMesh) this.facesMesh.visible = on;
    this.requestRender();
  }

  setSurfaceVisible(on) {
    this.showSurface = on;
    if (this.surfaceMesh) this.surfaceMesh.visible = on;
    this.requestRender();
  }

  /** Highlights the struts whose kind is in `kindIds` (numbers 0..8); null restores the colours. */
  highlightKinds(kindIds) {
    this.highlighted = kindIds;
    const kinds = this.snapshot?.kinds;
    const dim = new THREE.Color(0x555a63), glow = new THREE.Color(COLOURS.highlight);
    for (const { mesh, ids, base } of Object.values(this.struts)) {
      ids.forEach((strut, k) => {
        const colour = !kindIds ? base : kindIds.includes(kinds[strut]) ? glow : dim;
        mesh.setColorAt(k, colour);
      });
      if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
    }
    this.requestRender();
  }

  /** Frames the model (or the surface when there is no model). */
  fit() {
    const box = new THREE.Box3();
    this.modelGroup.updateMatrixWorld(true);
    if (this.modelGroup.children.length) box.expandByObject(this.modelGroup);
    else if (this.surfaceMesh) box.expandByObject(this.surfaceMesh);
    if (box.isEmpty()) return;
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const distance = sphere.radius / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2)) * 1.05;
    const view = new THREE.Vector3(0.55, 0.45, 1).normalize();
    this.camera.position.copy(sphere.center).addScaledVector(view, distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(sphere.center);
    this.controls.update();
    this.requestRender();
  }

  /** Fraction of canvas pixels close to each strut colour (tests and the API use it). */
  colourCoverage() {
    this.render(); // read in the same task as the draw (no preserveDrawingBuffer needed)
    const gl = this.renderer.getContext();
    const { width, height } = gl.canvas;
    const pixels = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const count = { blue: 0, yellow: 0, red: 0, background: 0 };
    for (let i = 0; i < pixels.length; i += 4) {
      const [r, g, b] = [pixels[i], pixels[i + 1], pixels[i + 2]];
      if (r === 0x20 && g === 0x24 && b === 0x2b) count.background++;
      else if (b > 110 && b > r * 1.6 && b > g * 1.2) count.blue++;
      else if (r > 130 && g > 100 && b < r * 0.5 && g > r * 0.55) count.yellow++;
      else if (r > 110 && g < r * 0.45 && b < r * 0.45) count.red++;
    }
    const total = width * height;
    return { width, height, blue: count.blue / total, yellow: count.yellow / total, red: count.red / total,
      background: count.background / total };
  }
}
