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
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
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
    this.struts = {}; // colour → {mesh, strutIds}
    this.balls = null;
    this.snapshot = null;
    this.showFaces = false;
    this.showSurface = false;
    this.highlighted = null;

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    this.renderer.setAnimationLoop(() => {
      this.controls.update();
      this.renderer.render(this.scene, this.camera);
    });
  }

  resize() {
    const { clientWidth: w, clientHeight: h } = this.container;
    if (!w || !h) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  clearModel() {
    for (const child of [...this.modelGroup.children]) {
      this.modelGroup.remove(child);
      child.geometry?.dispose();
      child.material?.dispose();
    }
    this.struts = {};
    this.balls = null;
    this.facesMesh = null;
  }

  /** Shows a snapshot (protocol.js Snapshot); `fit` frames it. */
  setModel(snapshot, { fit = false } = {}) {
    this.clearModel();
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
    for (const [colour, ids] of Object.entries(byColour)) {
      if (!ids.length) continue;
      const geometry = new THREE.CylinderGeometry(STRUT_RADIUS, STRUT_RADIUS, 1, SECTION_SIDES[colour], 1);
      const material = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.45, metalness: 0.05 });
      const mesh = new THREE.InstancedMesh(geometry, material, ids.length);
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
      this.modelGroup.add(mesh);
      this.struts[colour] = { mesh, ids, base };
    }

    const nodeCount = positions.length / 3;
    if (nodeCount) {
      const geometry = new THREE.SphereGeometry(BALL_RADIUS, 18, 12);
      const material = new THREE.MeshStandardMaterial({ color: COLOURS.ball, roughness: 0.35 });
      const mesh = new THREE.InstancedMesh(geometry, material, nodeCount);
      const p = new THREE.Vector3();
      for (let i = 0; i < nodeCount; i++) mesh.setMatrixAt(i, m.makeTranslation(p.fromArray(positions, 3 * i)));
      this.modelGroup.add(mesh);
      this.balls = mesh;
    }

    if (triangles.length) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
      geometry.computeVertexNormals();
      const material = new THREE.MeshStandardMaterial({
        color: 0x9aa7b8, transparent: true, opacity: 0.45, side: THREE.DoubleSide, depthWrite: false,
      });
      this.facesMesh = new THREE.Mesh(geometry, material);
      this.facesMesh.visible = this.showFaces;
      this.modelGroup.add(this.facesMesh);
    }
    if (this.highlighted) this.highlightKinds(this.highlighted);
    if (fit) this.fit();
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
  }

  setFacesVisible(on) {
    this.showFaces = on;
    if (this.facesMesh) this.facesMesh.visible = on;
  }

  setSurfaceVisible(on) {
    this.showSurface = on;
    if (this.surfaceMesh) this.surfaceMesh.visible = on;
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
      mesh.instanceColor.needsUpdate = true;
    }
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
  }

  /** Fraction of canvas pixels close to each strut colour (tests and the API use it). */
  colourCoverage() {
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
