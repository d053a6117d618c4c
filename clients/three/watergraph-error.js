// The error the client throws for a manifest or scene description it cannot run and for
// files that cannot be loaded. Its own module so that the manifest checks
// (watergraph-manifest.js) need no three.js; watergraph-three.js and watergraph-passes.js
// export it too.
export class WaterGraphError extends Error {
  // field: for a manifest that does not have its documented shape, the path of the member
  // at fault ("uniforms[2].builtin"), also named in the message.
  constructor(message, { field } = {}) {
    super(message);
    this.name = 'WaterGraphError';
    if (field !== undefined) this.field = field;
  }
}
