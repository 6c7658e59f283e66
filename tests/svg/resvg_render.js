// Renders SVG files with resvg (tests/test_svg_peers.sh, tests/test_svg_text.sh): node resvg_render.js WIDTH OUT_DIR LIST [FIRST]
// LIST names the files, one a line; the N-th (from 0) becomes OUT_DIR/N.png, from N = FIRST on;
// a failure is printed (a panic in resvg ends the process: the caller goes on after that file).
const { Resvg } = require(process.env.CG_RESVG_MODULE || '@resvg/resvg-js');
const fs = require('fs');
const path = require('path');
const width = parseInt(process.argv[2]);
const outDir = process.argv[3];
const files = fs.readFileSync(process.argv[4], 'utf8').split('\n').filter((f) => f.length > 0);
const first = parseInt(process.argv[5] || '0');
// CG_RESVG_FONT_DIR (tests/test_svg_text.sh): the only font folders resvg sees (colon-separated),
// DejaVu Sans the default family
const font = process.env.CG_RESVG_FONT_DIR
  ? { loadSystemFonts: false, fontDirs: process.env.CG_RESVG_FONT_DIR.split(':'), defaultFontFamily: 'DejaVu Sans' }
  : { loadSystemFonts: false };
files.forEach((file, index) => {
  if (index < first) return;
  try {
    const svg = fs.readFileSync(file);
    const r = new Resvg(svg, { fitTo: { mode: 'width', value: width }, font });
    fs.writeFileSync(path.join(outDir, index + '.png'), r.render().asPng());
  } catch (e) {
    console.error(file + ': ' + e.message);
  }
});
