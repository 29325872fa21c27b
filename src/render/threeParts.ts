/**
 * The parts of three.js the page uses, each from its own module of three's sources, which Vite
 * resolves `three` to in the site's build (vite.config.ts). three's package marks its sources
 * free of side effects, so the modules no part needs (the animation system, the loaders, the
 * other geometries, materials and objects) are left out; its bundled `build/three.module.js` keeps
 * them through top-level prototype writes that a bundler must assume have effects.
 * Every value the page imports from `three` must be exported here (the build fails otherwise).
 */

export { PerspectiveCamera } from 'three/src/cameras/PerspectiveCamera.js';
export { DoubleSide } from 'three/src/constants.js';
export { BufferAttribute } from 'three/src/core/BufferAttribute.js';
export { BufferGeometry } from 'three/src/core/BufferGeometry.js';
export { Object3D } from 'three/src/core/Object3D.js';
export { SphereGeometry } from 'three/src/geometries/SphereGeometry.js';
export { AmbientLight } from 'three/src/lights/AmbientLight.js';
export { DirectionalLight } from 'three/src/lights/DirectionalLight.js';
export { MeshBasicMaterial } from 'three/src/materials/MeshBasicMaterial.js';
export { MeshLambertMaterial } from 'three/src/materials/MeshLambertMaterial.js';
export { MeshStandardMaterial } from 'three/src/materials/MeshStandardMaterial.js';
export { PointsMaterial } from 'three/src/materials/PointsMaterial.js';
export { ShaderMaterial } from 'three/src/materials/ShaderMaterial.js';
export { Box3 } from 'three/src/math/Box3.js';
export { Color } from 'three/src/math/Color.js';
export { Quaternion } from 'three/src/math/Quaternion.js';
export { Sphere } from 'three/src/math/Sphere.js';
export { Vector3 } from 'three/src/math/Vector3.js';
export { Group } from 'three/src/objects/Group.js';
export { Mesh } from 'three/src/objects/Mesh.js';
export { Points } from 'three/src/objects/Points.js';
export { WebGLRenderer } from 'three/src/renderers/WebGLRenderer.js';
export { Scene } from 'three/src/scenes/Scene.js';
