// Validates glTF files with the Khronos glTF validator and prints one line a
// file: "FILE: E errors, W warnings, I infos, H hints", then each error as
// "  ERROR CODE POINTER: MESSAGE".  Exit status 1 when any file has an error
// or cannot be read, 0 otherwise.
// usage: CG_GLTF_VALIDATOR=DIR/gltf-validator node validate.js FILE...
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require(process.env.CG_GLTF_VALIDATOR || 'gltf-validator');

async function validate(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (err, data) =>
          err ? reject(err.toString()) : resolve(new Uint8Array(data)));
      }),
  });
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ` +
              `${i.numInfos} infos, ${i.numHints} hints`);
  for (const m of i.messages)
    if (m.severity <= (process.env.CG_GLTF_SHOW_WARNINGS ? 1 : 0))
      console.log(`  ${m.severity === 0 ? 'ERROR' : 'WARNING'} ${m.code} ${m.pointer || ''}: ${m.message}`);
  return i.numErrors;
}

(async () => {
  let failed = 0;
  for (const file of process.argv.slice(2)) {
    try {
      if (await validate(file)) failed++;
    } catch (e) {
      console.log(`${file}: the validator failed: ${e}`);
      failed++;
    }
  }
  process.exit(failed ? 1 : 0);
})();
