// The 3-D scene of a replay: the ground with a metre grid and the path so far, the robot as
// its plant draws itself (plant/plant_drawing.h: two wheels, a cart if it has one, a body that
// pitches about the axle or the cart's top; or a model file's own shapes, model_robot.js),
// lights, and a camera that follows the robot. It
// needs WebGL 2 (three.js's renderer does); openRobotScene says when the browser cannot give it.
//
// cbbg's frame is x forward, y left, z up; three.js's is y up. A point (x, y, z) of cbbg is
// (x, z, -y) here, a heading (yaw about z) is a rotation about three.js's y.

import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import { ModelRobot } from "./model_robot.js";

// The ground is a square of GROUND_SIZE about the robot, moved under it in steps of
// GROUND_STEP so that its lines stay where they are on the ground. Its lines are drawn in
// pieces of SEGMENT, since some renderers (SwiftShader, a headless browser's) drop a line
// that passes behind the camera.
const GROUND_SIZE = 80; // m
const GROUND_STEP = 10; // m
const SEGMENT = 2;      // m
const CAMERA_OFFSET = new THREE.Vector3(1.6, 1.1, 2.2);

function wheel(robot, side, material, markMaterial) {
  // side: +1 left (cbbg's +y, three.js's -z), -1 right.
  const group = new THREE.Group();
  group.position.set(0, 0, -side * robot.track_width / 2);
  const width = 0.05;
  const tyre = new THREE.Mesh(new THREE.CylinderGeometry(robot.wheel_radius, robot.wheel_radius,
                                                         width, 40), material);
  tyre.rotation.x = Math.PI / 2; // the cylinder's axis along the axle
  group.add(tyre);
  // A spoke, so that the wheel's turning shows.
  const spoke = new THREE.Mesh(new THREE.BoxGeometry(robot.wheel_radius * 1.9, 0.03,
                                                     width * 1.1), markMaterial);
  group.add(spoke);
  return group;
}

function body(robot) {
  const group = new THREE.Group(); // pitches about the pivot: the axle, or the cart's top
  group.position.y = robot.cart_height;
  const length = robot.body_length;
  const half = robot.body_thickness / 2;
  const shell = new THREE.Mesh(
    new THREE.BoxGeometry(robot.body_thickness, length, robot.body_width),
    new THREE.MeshStandardMaterial({ color: 0x4a78b5 }));
  shell.position.y = length / 2;
  group.add(shell);
  // The front, so that which way it leans shows.
  const front = new THREE.Mesh(new THREE.BoxGeometry(0.01, length * 0.9, robot.body_width * 0.7),
                               new THREE.MeshStandardMaterial({ color: 0xf2b134 }));
  front.position.set(half + 0.005, length / 2, 0);
  group.add(front);
  const mass = new THREE.Mesh(new THREE.SphereGeometry(0.04, 20, 12),
                              new THREE.MeshStandardMaterial({ color: 0xd94f4f }));
  mass.position.set(half + 0.02, robot.com_height, 0);
  group.add(mass);
  return group;
}

// The cart on the axle, from the axle up to the pivot; it turns with the heading, never
// pitches. Null for a plant without one (cart_length 0: a two-wheeler).
function cart(robot) {
  if (!(robot.cart_length > 0 && robot.cart_height > 0)) return null;
  const box = new THREE.Mesh(new THREE.BoxGeometry(robot.cart_length, robot.cart_height,
                                                   Math.max(robot.track_width - 0.06, 0.02)),
                             new THREE.MeshStandardMaterial({ color: 0x6c757d }));
  box.position.y = robot.cart_height / 2;
  return box;
}

// Lines every `step` metres across the ground, as one set of segments.
function gridLines(step, colour, height) {
  const half = GROUND_SIZE / 2;
  const points = [];
  for (let v = -half; v <= half; v += step) {
    for (let u = -half; u < half; u += SEGMENT) {
      points.push(new THREE.Vector3(v, 0, u), new THREE.Vector3(v, 0, u + SEGMENT));
      points.push(new THREE.Vector3(u, 0, v), new THREE.Vector3(u + SEGMENT, 0, v));
    }
  }
  const lines = new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(points),
                                       new THREE.LineBasicMaterial({ color: colour }));
  lines.position.y = height;
  return lines;
}

function ground() {
  const group = new THREE.Group();
  // Pushed back in depth, so that the lines on it win however coarse the depth buffer.
  const plane = new THREE.Mesh(new THREE.PlaneGeometry(GROUND_SIZE, GROUND_SIZE),
                               new THREE.MeshStandardMaterial({ color: 0xe9ecef,
                                                                polygonOffset: true,
                                                                polygonOffsetFactor: 4,
                                                                polygonOffsetUnits: 4 }));
  plane.rotation.x = -Math.PI / 2;
  group.add(plane);
  group.add(gridLines(1, 0xb0b8c1, 0.005), gridLines(10, 0x59636e, 0.01));
  return group;
}

// A renderer on `canvas`, or null where the browser offers no WebGL 2 context. The context
// is asked for first, so that a browser without WebGL is told apart from a failure.
function webglRenderer(canvas) {
  // Kept drawn after each frame, so that a screenshot of the view shows it.
  const attributes = { antialias: true, preserveDrawingBuffer: true };
  const context = canvas.getContext("webgl2", attributes);
  if (!context) return null;
  return new THREE.WebGLRenderer({ canvas, context, ...attributes });
}

// The scene on `canvas`, or null when it cannot be drawn there: the page goes on without it.
export function openRobotScene(canvas, robot) {
  try {
    const renderer = webglRenderer(canvas);
    return renderer && new RobotScene(renderer, canvas, robot);
  } catch (error) {
    console.warn(`cbbg replay: no 3-D view: ${error.message}`);
    return null;
  }
}

class RobotScene {
  constructor(renderer, canvas, robot) {
    this.robot = robot;
    this.renderer = renderer;
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xf8f9fa);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8d99a6, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(3, 6, 2);
    this.scene.add(sun);
    this.ground = ground();
    this.scene.add(this.ground);
    this.path = new THREE.LineSegments(new THREE.BufferGeometry(),
                                       new THREE.LineBasicMaterial({ color: 0xd94f4f }));
    this.path.position.y = 0.015;
    this.scene.add(this.path);

    this.anchor = new THREE.Vector3(); // the pose's point on the ground, which the camera follows
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.1, 500);
    const target = new THREE.Vector3(0, robot.wheel_radius + robot.cart_height + robot.com_height, 0);
    if (robot.model) {
      this.model = new ModelRobot(robot.model);
      this.scene.add(this.model.group);
      // The camera as far from the robot as its size asks, looking at its middle.
      const bounds = this.model.bounds();
      bounds.getCenter(target);
      const scale = Math.min(4, Math.max(0.4, bounds.getSize(new THREE.Vector3()).length() / 1.2));
      this.camera.position.copy(CAMERA_OFFSET).multiplyScalar(scale).add(target);
    } else {
      this.addTwoWheeler(robot);
      this.camera.position.copy(CAMERA_OFFSET).add(new THREE.Vector3(0, robot.wheel_radius, 0));
    }
    this.shapeCount = this.model ? this.model.shapeCount : 0;
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.target.copy(target);
    this.controls.update();
  }

  addTwoWheeler(robot) {
    this.base = new THREE.Group(); // at the axle, turned by the heading
    this.body = body(robot);
    const tyre = new THREE.MeshStandardMaterial({ color: 0x2b2f33 });
    const mark = new THREE.MeshStandardMaterial({ color: 0xf2f2f2 });
    this.left = wheel(robot, +1, tyre, mark);
    this.right = wheel(robot, -1, tyre, mark);
    this.base.add(this.body, this.left, this.right);
    const carried = cart(robot);
    if (carried) this.base.add(carried);
    this.scene.add(this.base);
  }

  // The path the axle takes over a trial, drawn on the ground as the segments between
  // ticks, leaving out those with an end that is not a number (null in a diverged log).
  setPath(xs, ys) {
    const points = [];
    const known = (i) => Number.isFinite(xs[i]) && Number.isFinite(ys[i]);
    for (let i = 1; i < xs.length; ++i) {
      if (!known(i - 1) || !known(i)) continue;
      points.push(new THREE.Vector3(xs[i - 1], 0, -ys[i - 1]), new THREE.Vector3(xs[i], 0, -ys[i]));
    }
    this.path.geometry.dispose();
    this.path.geometry = new THREE.BufferGeometry().setFromPoints(points);
  }

  // pose: {x, y, yaw, theta_b, phi_l, phi_r}; the camera moves with the robot.
  show(pose) {
    const before = this.anchor.clone();
    this.anchor.set(pose.x, 0, -pose.y);
    if (this.model) {
      this.model.show(pose);
    } else {
      this.base.position.set(pose.x, this.robot.wheel_radius, -pose.y);
      this.base.rotation.y = pose.yaw;
      this.body.rotation.z = -pose.theta_b; // > 0 leans forward
      this.left.rotation.z = -pose.phi_l;   // rolling forward turns the top forward
      this.right.rotation.z = -pose.phi_r;
    }
    this.ground.position.set(Math.round(pose.x / GROUND_STEP) * GROUND_STEP, 0,
                             -Math.round(pose.y / GROUND_STEP) * GROUND_STEP);
    const moved = this.anchor.clone().sub(before);
    this.camera.position.add(moved);
    this.controls.target.add(moved);
    this.controls.update();
  }

  resize(width, height) {
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / Math.max(height, 1);
    this.camera.updateProjectionMatrix();
  }

  render() {
    this.renderer.render(this.scene, this.camera);
  }
}
