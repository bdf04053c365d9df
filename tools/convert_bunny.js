#!/usr/bin/env node
// Converts the npm package "bunny" (the Stanford bunny as {positions, cells})
// into the OBJ that scenes/cornell_bunny.json uses. Run once by hand; the
// result is committed as scenes/meshes/bunny.obj, so builds need no network.
//
//   cd /tmp && npm pack bunny && tar xzf bunny-*.tgz      # gives /tmp/package
//   node tools/convert_bunny.js /tmp/package scenes/meshes/bunny.obj
//
// Keep the package and its tarball out of the repository. No normals are
// written: the scene loader computes smooth vertex normals for meshes without.
'use strict';

const fs = require('fs');
const path = require('path');

function main() {
  const [pkgDir, outPath] = process.argv.slice(2);
  if (!pkgDir || !outPath) {
    console.error('usage: node tools/convert_bunny.js <unpacked bunny package dir> <output .obj>');
    process.exit(2);
  }
  const dir = path.resolve(pkgDir);
  const meta = JSON.parse(fs.readFileSync(path.join(dir, 'package.json'), 'utf8'));
  const { positions, cells } = require(path.join(dir, meta.main || 'index.js'));

  for (const c of cells) {
    if (c.length !== 3 || c.some((i) => !Number.isInteger(i) || i < 0 || i >= positions.length)) {
      throw new Error(`bad face ${JSON.stringify(c)}`);
    }
  }

  const lines = [
    '# The Stanford Bunny',
    '# Source: Stanford Computer Graphics Laboratory, The Stanford 3D Scanning Repository',
    '#         http://graphics.stanford.edu/data/3Dscanrep/',
    `# Taken from the npm package "${meta.name}" ${meta.version} by ${meta.author}` +
      ` (licence as stated in its package.json: ${meta.license}),`,
    '# converted by tools/convert_bunny.js.',
    `# ${positions.length} vertices, ${cells.length} triangles (a reduced-resolution scan); y up,` +
      ' lowest point at y = 0 (to 0.003), about 10 units wide; faces counter-clockwise seen from outside.',
  ];
  // Six significant digits is what the package itself stores.
  for (const p of positions) lines.push(`v ${p[0]} ${p[1]} ${p[2]}`);
  for (const c of cells) lines.push(`f ${c[0] + 1} ${c[1] + 1} ${c[2] + 1}`);
  fs.writeFileSync(outPath, lines.join('\n') + '\n');
  console.error(`wrote ${outPath}: ${positions.length} vertices, ${cells.length} triangles`);
}

main();
