// A robot drawn from its model file's own shapes (cbbg's plant_drawing.h, ModelDrawing): a
// tree of bodies, each placed on its parent as the model places it at rest and moved by its
// joints as MuJoCo moves them (a hinge turns about its axis through its anchor, a slide
// shifts along its axis, each by its value less its rest value). A joint follows the logged
// column it names; one that names none stays at rest.
//
// The model's frame is z up, quaternions (w, x, y, z); the group turns it to three.js's y up.

import * as THREE from "three";

const vector = ([x, y, z]) => new THREE.Vector3(x, y, z);
const quaternion = ([w, x, y, z]) => new THREE.Quaternion(x, y, z, w);

// three.js's round shapes have their axis along y; the model's along z.
function geometry(shape) {
  const [a, b, c] = shape.size;
  switch (shape.kind) {
    case "sphere": return new THREE.SphereGeometry(a, 32, 16);
    case "ellipsoid": return new THREE.SphereGeometry(1, 32, 16).scale(a, b, c);
    case "capsule": return new THREE.CapsuleGeometry(a, 2 * b, 8, 24).rotateX(Math.PI / 2);
    case "cylinder": return new THREE.CylinderGeometry(a, a, 2 * b, 40).rotateX(Math.PI / 2);
    default: return new THREE.BoxGeometry(2 * a, 2 * b, 2 * c); // a box, or a mesh's box
  }
}

function material(colour) {
  const [r, g, b, opacity] = colour;
  return new THREE.MeshStandardMaterial({ color: new THREE.Color().setRGB(r, g, b, THREE.SRGBColorSpace),
                                          transparent: opacity < 1, opacity });
}

// The shape as a mesh in its body's frame; a cylinder (a wheel, a flywheel) with a bar
// across it, so that its turning shows.
function mesh(shape) {
  const solid = new THREE.Mesh(geometry(shape), material(shape.colour));
  solid.position.copy(vector(shape.position));
  solid.quaternion.copy(quaternion(shape.orientation));
  if (shape.kind === "cylinder") {
    const [radius, half] = shape.size;
    const bar = new THREE.Mesh(new THREE.BoxGeometry(1.9 * radius, Math.min(0.03, radius / 4), 2.2 * half),
                               new THREE.MeshStandardMaterial({ color: 0xf2f2f2 }));
    solid.add(bar);
  }
  return solid;
}

export class ModelRobot {
  constructor(model) {
    this.model = model;
    this.group = new THREE.Group();
    this.group.rotation.x = -Math.PI / 2; // the model's z up is three.js's y up
    const ground = new THREE.Group();
    this.frames = model.bodies.map(() => new THREE.Group());
    this.group.add(ground, ...this.frames);
    for (const shape of model.shapes) {
      (shape.body >= 0 ? this.frames[shape.body] : ground).add(mesh(shape));
    }
    this.shapeCount = model.shapes.length;
    this.show(null);
  }

  // Places every body for the logged values `pose` (by column); null: every joint at rest.
  show(pose) {
    const positions = [];
    const orientations = [];
    this.model.bodies.forEach((body, i) => {
      const parentAt = body.parent >= 0 ? positions[body.parent] : new THREE.Vector3();
      const parentTurn = body.parent >= 0 ? orientations[body.parent] : new THREE.Quaternion();
      const turn = parentTurn.clone().multiply(quaternion(body.orientation));
      const at = vector(body.position).applyQuaternion(parentTurn).add(parentAt);
      for (const joint of body.joints) {
        const value = pose && joint.column !== null ? pose[joint.column] : joint.rest;
        const moved = Number.isFinite(value) ? value - joint.rest : 0;
        const axis = vector(joint.axis).normalize();
        if (joint.kind === "hinge") {
          const anchor = vector(joint.anchor).applyQuaternion(turn).add(at);
          turn.multiply(new THREE.Quaternion().setFromAxisAngle(axis, moved));
          at.copy(anchor).sub(vector(joint.anchor).applyQuaternion(turn));
        } else {
          at.add(axis.applyQuaternion(turn).multiplyScalar(moved));
        }
      }
      positions.push(at);
      orientations.push(turn);
      this.frames[i].position.copy(at);
      this.frames[i].quaternion.copy(turn);
    });
  }

  // The box about the robot as it stands now, in three.js's frame.
  bounds() {
    this.group.updateMatrixWorld(true);
    return new THREE.Box3().setFromObject(this.group);
  }
}
