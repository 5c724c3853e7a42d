// Runs the Khronos glTF-Validator on .gltf and .glb files (and on those in
// the directories given, not recursively) and prints each file's counts.
// Exits 1 if any file has an error, or with --expect-errors if any file has
// none; 2 when there is nothing to validate.
// Usage: node validate_gltf.mjs [--expect-errors] FILE|DIR...
import { readdir, readFile, stat } from 'node:fs/promises';
import path from 'node:path';
import validator from 'gltf-validator';

const args = process.argv.slice(2);
const expectErrors = args.includes('--expect-errors');
const files = [];
for (const arg of args.filter((a) => a !== '--expect-errors')) {
  if ((await stat(arg)).isDirectory()) {
    const names = (await readdir(arg)).filter((n) => /\.(gltf|glb)$/i.test(n)).sort();
    files.push(...names.map((n) => path.join(arg, n)));
  } else {
    files.push(arg);
  }
}
if (files.length === 0) {
  console.error('validate_gltf: no .gltf or .glb files given');
  process.exit(2);
}

let failed = false;
for (const file of files) {
  const report = await validator.validateBytes(new Uint8Array(await readFile(file)), {
    uri: file,
    // Exported files are self-contained: any external reference is a bug.
    externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri}`)),
  });
  const { numErrors, numWarnings, numInfos, messages } = report.issues;
  console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos (validator ${report.validatorVersion})`);
  for (const m of messages.filter((m) => m.severity <= 1)) {
    console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} at ${m.pointer ?? m.offset ?? ''}: ${m.message}`);
  }
  if (expectErrors ? numErrors === 0 : numErrors > 0) failed = true;
}
if (failed) {
  console.error(expectErrors ? 'validate_gltf: a file that should be rejected was accepted' : 'validate_gltf: errors found');
  process.exit(1);
}
