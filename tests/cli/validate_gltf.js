// Validates a glTF or GLB file with the Khronos gltf-validator (npm) and prints its report's
// counts and first messages as JSON. External buffers are read from the file's folder.
const fs = require("fs");
const path = require("path");
const validator = require(process.env.GLTF_VALIDATOR_MODULE || "gltf-validator");

const file = process.argv[2];
const readResource = (uri) =>
  new Promise((resolve, reject) => {
    try {
      resolve(new Uint8Array(fs.readFileSync(path.join(path.dirname(file), decodeURIComponent(uri)))));
    } catch (error) {
      reject(error.toString());
    }
  });

validator
  .validateBytes(new Uint8Array(fs.readFileSync(file)), {uri: path.basename(file), externalResourceFunction: readResource})
  .then((report) => {
    const issues = report.issues;
    console.log(JSON.stringify({errors: issues.numErrors, warnings: issues.numWarnings,
                                messages: issues.messages.slice(0, 10)}));
  })
  .catch((error) => {
    console.log(JSON.stringify({errors: -1, messages: [String(error)]}));
  });
