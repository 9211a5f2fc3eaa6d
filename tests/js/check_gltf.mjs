// Runs a .glb through the two readers the tests hold the project's glTF exports to: the Khronos
// glTF-Validator (the spec's own checker) and three.js's GLTFLoader (what web clients use).
// Usage: node check_gltf.mjs FILE.glb (or a .gltf, whose files beside it the validator reads;
// three.js loads .glb files only here) — prints one JSON object:
//   {"validator": {"errors": n, "warnings": n, "messages": [{"code", "severity", "pointer", "message"}]},
//    "three": {"error": "…" | null, "animations": [{"name", "duration", "tracks"}],
//              "meshes": n, "skinnedMeshes": n, "bones": n, "morphTargets": n}}
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';

// GLTFLoader looks for a browser's global object when it meets an image.
globalThis.self ??= globalThis;
import validator from 'gltf-validator';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const path = process.argv[2];
const bytes = readFileSync(path);

// A .gltf's buffers and images are files beside it.
const externalResourceFunction = (uri) => Promise.resolve(new Uint8Array(readFileSync(join(dirname(path), decodeURIComponent(uri)))));
const report = await validator.validateBytes(new Uint8Array(bytes), { uri: path, maxIssues: 1000, externalResourceFunction });
const severities = ['error', 'warning', 'info', 'hint'];
const validated = {
    errors: report.issues.numErrors,
    warnings: report.issues.numWarnings,
    messages: report.issues.messages.map((m) => ({
        code: m.code, severity: severities[m.severity] ?? String(m.severity), pointer: m.pointer ?? '', message: m.message,
    })),
};

// Textures cannot be decoded without a DOM; the loader reports and goes on, which is all a
// geometry and animation check needs.
const quiet = console.error;
console.error = () => {};
console.warn = () => {};
const three = { error: null, animations: [], meshes: 0, skinnedMeshes: 0, bones: 0, morphTargets: 0 };
try {
    const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
    const gltf = await new GLTFLoader().parseAsync(buffer, '');
    for (const clip of gltf.animations)
        three.animations.push({ name: clip.name, duration: clip.duration, tracks: clip.tracks.length });
    gltf.scene.traverse((object) => {
        if (object.isSkinnedMesh) three.skinnedMeshes += 1;
        if (object.isMesh) {
            three.meshes += 1;
            three.morphTargets += (object.morphTargetInfluences ?? []).length;
        }
        if (object.isBone) three.bones += 1;
    });
} catch (error) {
    three.error = String(error && error.message ? error.message : error);
}
console.error = quiet;
process.stdout.write(JSON.stringify({ validator: validated, three }) + '\n');
