// Renders SVG files with resvg (tests/test_svg_peers.sh): node resvg_render.js WIDTH OUT_DIR FILE...
// Each FILE.svg becomes OUT_DIR/N.png, N its position in the list; a failure is printed.
const { Resvg } = require(process.env.CG_RESVG_MODULE || '@resvg/resvg-js');
const fs = require('fs');
const path = require('path');
const width = parseInt(process.argv[2]);
const outDir = process.argv[3];
const files = process.argv.slice(4);
files.forEach((file, index) => {
  try {
    const svg = fs.readFileSync(file);
    const r = new Resvg(svg, { fitTo: { mode: 'width', value: width }, font: { loadSystemFonts: false } });
    fs.writeFileSync(path.join(outDir, index + '.png'), r.render().asPng());
  } catch (e) {
    console.error(file + ': ' + e.message);
  }
});
