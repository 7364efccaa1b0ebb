// The airshape viewer: the aircraft lit and shaded, orbit/pan/zoom (three.js OrbitControls),
// the component tree (show, hide, isolate, highlight), measures of the component picked, the
// name under the pointer, mirrored halves on or off, and a length scale. window.AIRSHAPE says
// what to show: {title, live, model (base64 GLB, or null when live), components: [{name, type,
// volume, area, box: {min, max}, faces: [face names in the order of the mesh's primitives],
// edges: [polylines x0, y0, z0, x1, ... in the page's frame]}]}. Live pages fetch /model.glb and
// /components.json and poll /version, reloading when the file changed and showing its error
// when it no longer loads; they have a slider per control device (GET /devices, POST /deflect).
(function () {
  'use strict';

  const config = window.AIRSHAPE;
  const view = document.getElementById('view');
  const renderer = new THREE.WebGLRenderer({ antialias: true, alpha: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  view.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 0.75));
  const sun = new THREE.DirectionalLight(0xffffff, 0.6);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1e6);
  camera.up.set(0, 1, 0);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.addEventListener('change', render);

  let components = [];       // as config.components says
  let objects = new Map();   // component name -> its three.js object
  let model = null;          // the glTF scene shown
  let selected = null;
  let edges = [];

  document.getElementById('title').textContent = config.title;

  function render() {
    sun.position.copy(camera.position);
    renderer.render(scene, camera);
    updateScale();
  }

  function resize() {
    const width = view.clientWidth, height = view.clientHeight;
    renderer.setSize(width, height);
    camera.aspect = width / Math.max(height, 1);
    camera.updateProjectionMatrix();
    render();
  }
  window.addEventListener('resize', resize);

  /// A length of 1, 2 or 5 times a power of ten drawn about 100 pixels long at the orbit's centre.
  function updateScale() {
    const distance = camera.position.distanceTo(controls.target);
    const metresPerPixel = 2 * distance * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2) /
                           Math.max(view.clientHeight, 1);
    const wanted = 100 * metresPerPixel;
    const power = Math.pow(10, Math.floor(Math.log10(wanted)));
    const length = [1, 2, 5, 10].map(f => f * power).filter(l => l <= wanted).pop() || power;
    document.getElementById('scale-bar').style.width = (length / metresPerPixel).toFixed(0) + 'px';
    document.getElementById('scale-label').textContent = length >= 1 ? length + ' m' : length * 1000 + ' mm';
  }

  /// Whether an object is drawn: it and every parent visible (the raycaster does not ask).
  function shown(object) {
    for (let o = object; o; o = o.parent) if (!o.visible) return false;
    return true;
  }

  function nameOf(object) { return (object.userData && object.userData.name) || object.name; }

  /// The component an object belongs to: itself or the nearest parent named as a component.
  function componentOf(object) {
    for (let o = object; o; o = o.parent) if (objects.has(nameOf(o))) return nameOf(o);
    return null;
  }

  /// The name of the face a mesh shows: a component's meshes are its glTF primitives, one per
  /// face, in the order of its `faces` list.
  function faceOf(name, mesh) {
    const component = components.find(c => c.name === name);
    const object = objects.get(name);
    if (!component || !component.faces || !object) return '';
    const meshes = object.isMesh ? [object] : object.children.filter(o => o.isMesh);
    return component.faces[meshes.indexOf(mesh)] || '';
  }

  function showModel(gltf) {
    if (model) scene.remove(model);
    model = gltf.scene;
    scene.add(model);
    objects = new Map();
    model.traverse(object => {
      const name = nameOf(object);
      if (components.some(c => c.name === name) && !objects.has(name)) objects.set(name, object);
      if (object.isMesh) {
        // Own materials, so that one component can be highlighted alone; both sides lit.
        object.material = new THREE.MeshStandardMaterial({ color: 0xc8d0da, metalness: 0.05, roughness: 0.65,
                                                           side: THREE.DoubleSide });
      }
    });
    for (const [name, object] of objects) {
      const type = (components.find(c => c.name === name) || {}).type;
      object.traverse(o => { if (o.isMesh) o.material.color.setHex(colourOf(type)); });
    }
    buildTree();
    setEdges(document.getElementById('edges').checked);
    applyMirrored();
    if (!showModel.framed) frame();
    showModel.framed = true;
    render();
    document.body.dataset.state = 'loaded';
  }

  /// A colour per kind of component, so that wings, bodies, engines and what lies inside them
  /// are told apart at a glance.
  function colourOf(type) {
    const colours = { fuselage: 0xe4e8ee, wing: 0xb9c7d8, engine_nacelle: 0x8d99a8, engine_pylon: 0xa3afbd,
                      control_surface: 0x7fa7d9, tank: 0xe0a458, duct: 0x8fc29a, rotor: 0xb9c7d8,
                      rotor_blade: 0xb9c7d8 };
    if (colours[type] !== undefined) return colours[type];
    return type && type.startsWith('wing_') ? 0xd98f6f : 0xc8d0da;
  }

  /// Looks at the whole aircraft from the front left, above.
  function frame() {
    const box = new THREE.Box3().setFromObject(model);
    const centre = box.getCenter(new THREE.Vector3());
    const size = box.getSize(new THREE.Vector3()).length() || 1;
    controls.target.copy(centre);
    camera.position.copy(centre).add(new THREE.Vector3(-0.9, 0.6, 1.1).normalize().multiplyScalar(size * 1.4));
    camera.near = size / 1000;
    camera.far = size * 100;
    camera.updateProjectionMatrix();
    controls.update();
  }

  function buildTree() {
    const tree = document.getElementById('tree');
    tree.textContent = '';
    for (const component of components) {
      const item = document.createElement('li');
      item.dataset.name = component.name;
      const shown = document.createElement('input');
      shown.type = 'checkbox';
      shown.checked = true;
      shown.title = 'show or hide';
      shown.addEventListener('click', event => {
        event.stopPropagation();
        setVisible(component.name, shown.checked);
      });
      const label = document.createElement('span');
      label.textContent = component.name;
      const type = document.createElement('span');
      type.className = 'type';
      type.textContent = component.type || '';
      item.append(shown, label, type);
      item.title = 'click: highlight and measures; double-click: show it alone';
      item.addEventListener('click', () => select(component.name));
      item.addEventListener('dblclick', () => isolate(component.name));
      tree.appendChild(item);
    }
  }

  function treeItem(name) {
    return [...document.querySelectorAll('#tree li')].find(li => li.dataset.name === name);
  }

  function setVisible(name, visible) {
    const object = objects.get(name);
    if (object) object.visible = visible;
    const item = treeItem(name);
    if (item) item.querySelector('input').checked = visible;
    render();
  }

  function isolate(name) {
    for (const other of objects.keys()) setVisible(other, other === name);
    select(name);
  }

  function highlight(name, on) {
    const object = objects.get(name);
    if (!object) return;
    object.traverse(o => { if (o.isMesh) o.material.emissive.setHex(on ? 0x2a5db0 : 0x000000); });
  }

  function format(value) { return typeof value === 'number' ? value.toPrecision(6) : '–'; }

  function select(name) {
    if (selected) highlight(selected, false);
    selected = name;
    highlight(name, true);
    document.querySelectorAll('#tree li').forEach(li => li.classList.toggle('selected', li.dataset.name === name));
    const c = components.find(component => component.name === name) || {};
    const box = c.box ? `\nbox min  ${c.box.min.map(format).join(' ')}\nbox max  ${c.box.max.map(format).join(' ')}` : '';
    document.getElementById('info').textContent =
        `${name}\ntype     ${c.type || '–'}\nvolume   ${format(c.volume)} m³\narea     ${format(c.area)} m²${box}`;
    render();
  }

  function applyMirrored() {
    const on = document.getElementById('mirrored').checked;
    for (const name of objects.keys()) if (name.endsWith(' (mirrored)')) setVisible(name, on);
  }

  /// The components' B-rep edges (section profiles, guide curves, segment borders, seams) as
  /// lines, each component's under its object so that hiding it hides them.
  function setEdges(on) {
    for (const line of edges) line.parent.remove(line);
    edges = [];
    if (on && model) {
      for (const component of components) {
        const object = objects.get(component.name);
        if (!object || !component.edges) continue;
        const positions = [];
        for (const polyline of component.edges)
          for (let i = 3; i < polyline.length; i += 3)
            positions.push(polyline[i - 3], polyline[i - 2], polyline[i - 1], polyline[i], polyline[i + 1], polyline[i + 2]);
        const geometry = new THREE.BufferGeometry();
        geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
        const line = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: 0x1d2733 }));
        // The polylines are in the page's frame: undo the object's own placement.
        object.updateWorldMatrix(true, false);
        line.applyMatrix4(object.matrixWorld.clone().invert());
        object.add(line);
        edges.push(line);
      }
    }
    render();
  }

  document.getElementById('mirrored').addEventListener('change', applyMirrored);
  document.getElementById('edges').addEventListener('change', event => setEdges(event.target.checked));
  document.getElementById('show-all').addEventListener('click', () => {
    for (const name of objects.keys()) setVisible(name, true);
    applyMirrored();
  });

  // The name under the pointer: the component, and the face's name where the file keeps it.
  const raycaster = new THREE.Raycaster();
  const hover = document.getElementById('hover');
  renderer.domElement.addEventListener('pointermove', event => {
    if (!model) return;
    const rect = renderer.domElement.getBoundingClientRect();
    const pointer = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1,
                                      -((event.clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(pointer, camera);
    const hit = raycaster.intersectObject(model, true).find(h => h.object.isMesh && shown(h.object));
    const name = hit && componentOf(hit.object);
    if (!name) { hover.hidden = true; return; }
    const face = faceOf(name, hit.object);
    hover.textContent = face ? `${name} · ${face}` : name;
    hover.style.left = (event.clientX + 12) + 'px';
    hover.style.top = (event.clientY + 12) + 'px';
    hover.hidden = false;
  });
  renderer.domElement.addEventListener('dblclick', () => {
    if (!hover.hidden) select(hover.textContent.split(' · ')[0]);
  });

  function showError(text) {
    const box = document.getElementById('error');
    box.textContent = text || '';
    box.hidden = !text;
  }

  function load(buffer, list) {
    components = list;
    new THREE.GLTFLoader().parse(buffer, '', showModel, error => showError('cannot show the model: ' + error));
  }

  function fromBase64(text) {
    const bytes = atob(text);
    const buffer = new Uint8Array(bytes.length);
    for (let i = 0; i < bytes.length; ++i) buffer[i] = bytes.charCodeAt(i);
    return buffer.buffer;
  }

  async function reload() {
    const [glb, list, devices] = await Promise.all([fetch('/model.glb').then(r => r.arrayBuffer()),
                                                    fetch('/components.json').then(r => r.json()),
                                                    fetch('/devices').then(r => r.json())]);
    load(glb, list);
    showDevices(devices);
  }

  /// Live: a slider per control device over its control parameter's range; letting go of one
  /// asks the server to rebuild the aircraft with the device there (the poll then reloads it).
  function showDevices(devices) {
    const box = document.getElementById('devices');
    box.textContent = '';
    box.hidden = devices.length === 0;
    if (box.hidden) return;
    const heading = document.createElement('h2');
    heading.textContent = 'control devices';
    box.appendChild(heading);
    for (const device of devices) {
      const row = document.createElement('label');
      row.className = 'device';
      const name = document.createElement('span');
      name.textContent = device.uid;
      const slider = document.createElement('input');
      Object.assign(slider, { type: 'range', min: device.min, max: device.max, value: device.value,
                              step: (device.max - device.min) / 100 || 0.01 });
      slider.dataset.uid = device.uid;
      const value = document.createElement('span');
      value.textContent = Number(device.value).toFixed(2);
      slider.addEventListener('input', () => { value.textContent = Number(slider.value).toFixed(2); });
      slider.addEventListener('change', () => fetch(
          `/deflect?uid=${encodeURIComponent(device.uid)}&parameter=${slider.value}`, { method: 'POST' }));
      row.append(name, slider, value);
      box.appendChild(row);
    }
  }

  /// Live: asks for the version each second; a new one is fetched, an error shown above the
  /// last good geometry.
  async function poll(shown) {
    let next = shown;
    try {
      const state = await (await fetch('/version')).json();
      showError(state.error);
      if (state.version !== shown && !state.error) {
        await reload();
        next = state.version;
        document.body.dataset.version = String(next);
      }
    } catch (error) {
      showError('the airshape view server does not answer (ended?)');
    }
    setTimeout(() => poll(next), 1000);
  }

  resize();
  if (config.live) {
    const stop = document.createElement('button');
    stop.type = 'button';
    stop.textContent = 'stop the server';
    stop.addEventListener('click', () => fetch('/quit', { method: 'POST' }));
    document.getElementById('panel').insertBefore(stop, document.getElementById('tree'));
    poll(-1);
  } else {
    load(fromBase64(config.model), config.components);
  }
})();
