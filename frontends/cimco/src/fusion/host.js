// postc's Fusion host API, in JavaScript: what Autodesk's post engine gives a
// `.cps` post (constants, settings, formats, output variables, sections,
// tools, vectors), and the engine functions (`__fusion_*`) that turn postc's
// events into Fusion's entry-point calls. It runs in postc's engine and in
// Node.js (the tests' referee) alike; docs/fusion.md says what each part does
// and which choices Autodesk's reference leaves open.

// ---- Constants (names from Autodesk's declarations, globals.d.ts) ----
var NUL = "";
var SOH = String.fromCharCode(1);
var STX = String.fromCharCode(2);
var ETX = String.fromCharCode(3);
var EOT = String.fromCharCode(4);
var ENQ = String.fromCharCode(5);
var ACK = String.fromCharCode(6);
var BEL = String.fromCharCode(7);
var BS = String.fromCharCode(8);
var TAB = String.fromCharCode(9);
var LF = String.fromCharCode(10);
var VT = String.fromCharCode(11);
var FF = String.fromCharCode(12);
var CR = String.fromCharCode(13);
var SO = String.fromCharCode(14);
var SI = String.fromCharCode(15);
var DLE = String.fromCharCode(16);
var DC1 = String.fromCharCode(17);
var DC2 = String.fromCharCode(18);
var DC3 = String.fromCharCode(19);
var DC4 = String.fromCharCode(20);
var NAK = String.fromCharCode(21);
var SYN = String.fromCharCode(22);
var ETB = String.fromCharCode(23);
var CAN = String.fromCharCode(24);
var EM = String.fromCharCode(25);
var SUB = String.fromCharCode(26);
var ESC = String.fromCharCode(27);
var FS = String.fromCharCode(28);
var GS = String.fromCharCode(29);
var RS = String.fromCharCode(30);
var US = String.fromCharCode(31);
var EOL = "\r\n";
var SP = " ";
var PATH_SEPARATOR = "\\";
var IN = 0;
var MM = 1;
var PLANE_XY = 0;
var PLANE_XZ = 1;
var PLANE_ZX = 1;
var PLANE_YZ = 2;
var X = 0;
var Y = 1;
var Z = 2;
var TOOL_AXIS_X = 0;
var TOOL_AXIS_Y = 1;
var TOOL_AXIS_Z = 2;
var RADIUS_COMPENSATION_OFF = 0;
var RADIUS_COMPENSATION_LEFT = 1;
var RADIUS_COMPENSATION_RIGHT = 2;
var SINGULARITY_LINEARIZE_OFF = 0;
var SINGULARITY_LINEARIZE_LINEAR = 1;
var SINGULARITY_LINEARIZE_ROTARY = 2;
var COOLANT_DISABLED = -1;
var COOLANT_OFF = 0;
var COOLANT_FLOOD = 1;
var COOLANT_MIST = 2;
var COOLANT_TOOL = 3;
var COOLANT_THROUGH_TOOL = 3;
var COOLANT_AIR = 4;
var COOLANT_AIR_THROUGH_TOOL = 5;
var COOLANT_SUCTION = 6;
var COOLANT_FLOOD_MIST = 7;
var COOLANT_FLOOD_THROUGH_TOOL = 8;
var MATERIAL_UNSPECIFIED = 0;
var MATERIAL_HSS = 1;
var MATERIAL_TI_COATED = 2;
var MATERIAL_CARBIDE = 3;
var MATERIAL_CERAMICS = 4;
var TOOL_UNSPECIFIED = 0;
var TOOL_DRILL = 1;
var TOOL_DRILL_CENTER = 2;
var TOOL_DRILL_SPOT = 3;
var TOOL_DRILL_BLOCK = 4;
var TOOL_MILLING_END_FLAT = 5;
var TOOL_MILLING_END_BALL = 6;
var TOOL_MILLING_END_BULLNOSE = 7;
var TOOL_MILLING_CHAMFER = 8;
var TOOL_MILLING_FACE = 9;
var TOOL_MILLING_SLOT = 10;
var TOOL_MILLING_RADIUS = 11;
var TOOL_MILLING_DOVETAIL = 12;
var TOOL_MILLING_TAPERED = 13;
var TOOL_MILLING_LOLLIPOP = 14;
var TOOL_TAP_RIGHT_HAND = 15;
var TOOL_TAP_LEFT_HAND = 16;
var TOOL_REAMER = 17;
var TOOL_BORING_BAR = 18;
var TOOL_COUNTER_BORE = 19;
var TOOL_COUNTER_SINK = 20;
var TOOL_HOLDER_ONLY = 21;
var TOOL_TURNING_GENERAL = 22;
var TOOL_TURNING_THREADING = 23;
var TOOL_TURNING_GROOVING = 24;
var TOOL_TURNING_BORING = 25;
var TOOL_TURNING_CUSTOM = 26;
var TOOL_PROBE = 27;
var TOOL_WIRE = 28;
var TOOL_WATER_JET = 29;
var TOOL_LASER_CUTTER = 30;
var TOOL_WELDER = 31;
var TOOL_GRINDER = 32;
var TOOL_MILLING_FORM = 33;
var TOOL_PLASMA_CUTTER = 34;
var TOOL_MARKER = 35;
var TOOL_MILLING_THREAD = 36;
var TOOL_COMPENSATION_INSERT_CENTER = 0;
var TOOL_COMPENSATION_TIP = 1;
var TOOL_COMPENSATION_TIP_CENTER = 2;
var TOOL_COMPENSATION_TIP_TANGENT = 3;
var HAS_PARAMETER = 1;
var HAS_RAPID = 2;
var HAS_LINEAR = 4;
var HAS_DWELL = 8;
var HAS_CIRCULAR = 16;
var HAS_CYCLE = 32;
var HAS_WELL_KNOWN_COMMAND = 64;
var HAS_COMMENT = 128;
var RECORD_INVALID = -1;
var RECORD_WELL_KNOWN_COMMAND = 0;
var RECORD_PARAMETER = 1;
var RECORD_LINEAR = 2;
var RECORD_LINEAR_5D = 3;
var RECORD_LINEAR_ZXN = 4;
var RECORD_CIRCULAR = 5;
var RECORD_DWELL = 6;
var RECORD_CYCLE = 7;
var RECORD_CYCLE_OFF = 8;
var RECORD_COMMENT = 9;
var RECORD_WIDE_COMMENT = 10;
var COMMAND_INVALID = -1;
var COMMAND_STOP = 0;
var COMMAND_OPTIONAL_STOP = 1;
var COMMAND_END = 2;
var COMMAND_SPINDLE_CLOCKWISE = 3;
var COMMAND_SPINDLE_COUNTERCLOCKWISE = 4;
var COMMAND_START_SPINDLE = 5;
var COMMAND_STOP_SPINDLE = 6;
var COMMAND_ORIENTATE_SPINDLE = 7;
var COMMAND_LOAD_TOOL = 8;
var COMMAND_COOLANT_ON = 9;
var COMMAND_COOLANT_OFF = 10;
var COMMAND_ACTIVATE_SPEED_FEED_SYNCHRONIZATION = 11;
var COMMAND_DEACTIVATE_SPEED_FEED_SYNCHRONIZATION = 12;
var COMMAND_LOCK_MULTI_AXIS = 13;
var COMMAND_UNLOCK_MULTI_AXIS = 14;
var COMMAND_EXACT_STOP = 15;
var COMMAND_START_CHIP_TRANSPORT = 16;
var COMMAND_STOP_CHIP_TRANSPORT = 17;
var COMMAND_OPEN_DOOR = 18;
var COMMAND_CLOSE_DOOR = 19;
var COMMAND_BREAK_CONTROL = 20;
var COMMAND_TOOL_MEASURE = 21;
var COMMAND_CALIBRATE = 22;
var COMMAND_VERIFY = 23;
var COMMAND_CLEAN = 24;
var COMMAND_ALARM = 25;
var COMMAND_ALERT = 26;
var COMMAND_CHANGE_PALLET = 27;
var COMMAND_POWER_ON = 28;
var COMMAND_POWER_OFF = 29;
var COMMAND_MAIN_CHUCK_OPEN = 30;
var COMMAND_MAIN_CHUCK_CLOSE = 31;
var COMMAND_SECONDARY_CHUCK_OPEN = 32;
var COMMAND_SECONDARY_CHUCK_CLOSE = 33;
var COMMAND_SECONDARY_SPINDLE_SYNCHRONIZATION_ACTIVATE = 34;
var COMMAND_SECONDARY_SPINDLE_SYNCHRONIZATION_DEACTIVATE = 35;
var COMMAND_SYNC_CHANNELS = 36;
var COMMAND_PROBE_ON = 37;
var COMMAND_PROBE_OFF = 38;
var MOVEMENT_RAPID = 0;
var MOVEMENT_LEAD_IN = 1;
var MOVEMENT_CUTTING = 2;
var MOVEMENT_LEAD_OUT = 3;
var MOVEMENT_LINK_TRANSITION = 4;
var MOVEMENT_LINK_DIRECT = 5;
var MOVEMENT_RAMP_HELIX = 6;
var MOVEMENT_RAMP_PROFILE = 7;
var MOVEMENT_RAMP_ZIG_ZAG = 8;
var MOVEMENT_RAMP = 9;
var MOVEMENT_PLUNGE = 10;
var MOVEMENT_PREDRILL = 11;
var MOVEMENT_EXTENDED = 12;
var MOVEMENT_REDUCED = 13;
var MOVEMENT_FINISH_CUTTING = 14;
var MOVEMENT_HIGH_FEED = 15;
var HIGH_FEED_NO_MAPPING = 0;
var HIGH_FEED_MAP_MULTI = 1;
var HIGH_FEED_MAP_XY_Z = 2;
var HIGH_FEED_MAP_ANY = 3;
// ---- Constants the declarations do not list ----
var DEG = 180 / Math.PI;
// The values of the Fusion API's PostCapabilities enumerator.
var CAPABILITY_MILLING = 1;
var CAPABILITY_TURNING = 2;
var CAPABILITY_SETUP_SHEET = 4;
var CAPABILITY_INTERMEDIATE = 8;
var CAPABILITY_JET = 16;
var CAPABILITY_CASCADING = 32;
var CAPABILITY_ADDITIVE = 64;
var CAPABILITY_INSPECTION = 128;
var CAPABILITY_MACHINE_SIMULATION = 256;
var TYPE_MILLING = 0;
var TYPE_TURNING = 1;
var TYPE_JET = 2;
var TYPE_ADDITIVE = 3;
var FEED_PER_MINUTE = 0;
var FEED_PER_REVOLUTION = 1;
var FEED_INVERSE_TIME = 2;
var FEED_FPM = 3;
var FEED_DPM = 4;
// Newer engines than the declarations name it; its value is postc's.
var FEED_DEGREES_MINUTE = 5;
var SPINDLE_PRIMARY = 0;
var SPINDLE_SECONDARY = 1;
var SPINDLE_CONSTANT_SPINDLE_SPEED = 0;
var SPINDLE_CONSTANT_SURFACE_SPEED = 1;
var JET_MODE_THROUGH = 0;
var JET_MODE_ETCHING = 1;
var JET_MODE_VAPORIZE = 2;
var OPTIMIZE_NONE = 0;
var OPTIMIZE_BOTH = 1;
var OPTIMIZE_TABLES = 2;
var OPTIMIZE_HEADS = 3;
var OPTIMIZE_AXIS = 4;
var TCP_MODE_OFF = 0;
var ENABLE_NONE = 0;
var ENABLE_RESET = 1;
var ENABLE_WCS = 2;
var ENABLE_LIMITS = 4;
var ENABLE_HOMING = 8;
var ENABLE_ALL = 15;
var PREFER_PREFERENCE = 0;
var PREFER_CLOSEST = 1;
var PREFER_POSITIVE = 2;
var PREFER_NEGATIVE = 3;
var PREFER_CW = 4;
var PREFER_CCW = 5;
var EULER_XYZ_S = 0;
var EULER_ZXZ_R = 1;
var EULER_ZYZ_R = 2;
var EULER_XYZ_R = 3;
var EULER_ZYX_R = 4;
var STRATEGY_DRILLING = 0;
var CONTROL_NONZERO = 1;
var CONTROL_FORCE = 2;
var DPM_STANDARD = 0;
var DPM_COMBINATION = 1;
var INVERSE_MINUTES = 0;
var INVERSE_SECONDS = 1;
var EXPAND_NONE = 0;
var EXPAND_TCP = 1;
var FORMAT_REAL = 0;
var ORIGINAL_UNIT = -1;

// ---- Settings a post assigns at its top (the engine reads them) ----
var description = "";
var vendor = "";
var vendorUrl = "";
var legal = "";
var certificationLevel = 0;
var minimumRevision = 0;
var longDescription = "";
var extension = "nc";
var filename = "";
var version = "";
var revision = 0;
var deprecated = false;
var capabilities = CAPABILITY_MILLING;
var tolerance = 0.002;
var mapWorkOrigin = true;
var mapToWCS = true;
var allowMachineChangeOnSection = false;
var minimumChordLength = 0.01;
var minimumCircularRadius = 0.01;
var maximumCircularRadius = 1000;
var minimumCircularSweep = 0.01 * Math.PI / 180;
var maximumCircularSweep = Math.PI;
var allowHelicalMoves = false;
var allowSpiralMoves = false;
var allowedCircularPlanes = undefined;
var highFeedMapping = HIGH_FEED_NO_MAPPING;
var highFeedrate = 0;
var properties = {};
var propertyDefinitions = {};
var groupDefinitions = {};
var keywords = "";
var programNameIsInteger = false;
var debugMode = false;
var preventPost = false;
var abortOnDeprecation = false;

// ---- What the engine hands the post ----
// The job's unit is known before the post's own top level runs, as
// Fusion's engine knows the document's (docs/fusion.md, choice 4).
var unit = __postc_jobUnitIsMm() ? MM : IN;
var outputUnit = unit;
var programName = "1001";
var programComment = "";
var tool = undefined;
var currentSection = undefined;
var cycle = undefined;
var cycleType = "";
var cycleExpanded = false;
var movement = MOVEMENT_CUTTING;
var radiusCompensation = RADIUS_COMPENSATION_OFF;
var feedrate = 0;
var spindleSpeed = 0;
var spindleAxis = TOOL_AXIS_Z;
var lineNumber = 0;
var end = undefined;
var machineConfiguration = undefined;
var machineParameters = {};
var initialCyclePosition = undefined;

// ---- Numbers ----
function toRad(degrees) { return degrees * Math.PI / 180; }
function toDeg(radians) { return radians * 180 / Math.PI; }
function spatial(value, u) { return (u == unit) ? value : ((u == MM) ? value / 25.4 : value * 25.4); }
function toPreciseUnit(value, u) { return spatial(value, u); }
function toUnit(value, u) { return spatial(value, u); }
function parseSpatial(text) { return parseFloat(text); }
function clamp(low, value, high) { return Math.max(low, Math.min(value, high)); }
function getAsInt(value) { return Math.floor(Number(value) + 0.5); }

function Range(minimum, maximum) {
  this.minimum = minimum;
  this.maximum = maximum;
  this.getMinimum = function () { return this.minimum; };
  this.getMaximum = function () { return this.maximum; };
  this.getSpan = function () { return this.maximum - this.minimum; };
  this.getMiddle = function () { return (this.minimum + this.maximum) / 2; };
  this.isNonRange = function () { return this.minimum > this.maximum; };
  this.expandTo = function (v) {
    if (v < this.minimum) { this.minimum = v; }
    if (v > this.maximum) { this.maximum = v; }
  };
  this.expandToRange = function (r) {
    this.expandTo(r.minimum);
    this.expandTo(r.maximum);
  };
}

function Vector(x, y, z) {
  if (x === undefined) { x = 0; }
  if (y === undefined) { y = 0; }
  if (z === undefined) { z = 0; }
  this.x = x;
  this.y = y;
  this.z = z;
  this.length = Math.sqrt(x * x + y * y + z * z);
}
// The methods are the prototype's, as the host's own vectors have them,
// so that `new Vector` makes no functions.
Vector.prototype.getX = function () { return this.x; };
Vector.prototype.getY = function () { return this.y; };
Vector.prototype.getZ = function () { return this.z; };
Vector.prototype.setX = function (v) { this.x = v; };
Vector.prototype.setY = function (v) { this.y = v; };
Vector.prototype.setZ = function (v) { this.z = v; };
Vector.prototype.getCoordinate = function (i) { return i == 0 ? this.x : (i == 1 ? this.y : this.z); };
Vector.prototype.setCoordinate = function (i, v) { if (i == 0) { this.x = v; } else if (i == 1) { this.y = v; } else { this.z = v; } };
Vector.prototype.getLength = function () { return Math.sqrt(this.x * this.x + this.y * this.y + this.z * this.z); };
Vector.prototype.getLength2 = function () { return this.x * this.x + this.y * this.y + this.z * this.z; };
Vector.prototype.isZero = function () { return this.x == 0 && this.y == 0 && this.z == 0; };
Vector.prototype.isNonZero = function () { return !this.isZero(); };
Vector.prototype.getNegated = function () { return new Vector(-this.x, -this.y, -this.z); };
Vector.prototype.negate = function () { this.x = -this.x; this.y = -this.y; this.z = -this.z; };
Vector.prototype.getAbsolute = function () { return new Vector(Math.abs(this.x), Math.abs(this.y), Math.abs(this.z)); };
Vector.prototype.getNormalized = function () {
  var l = this.getLength();
  return l == 0 ? new Vector(0, 0, 0) : new Vector(this.x / l, this.y / l, this.z / l);
};
Vector.prototype.normalize = function () { var n = this.getNormalized(); this.x = n.x; this.y = n.y; this.z = n.z; };
Vector.prototype.add = function (a, b, c) {
  if (b === undefined) { this.x += a.x; this.y += a.y; this.z += a.z; } else { this.x += a; this.y += b; this.z += c; }
};
Vector.prototype.subtract = function (a, b, c) {
  if (b === undefined) { this.x -= a.x; this.y -= a.y; this.z -= a.z; } else { this.x -= a; this.y -= b; this.z -= c; }
};
Vector.prototype.multiply = function (f) { this.x *= f; this.y *= f; this.z *= f; };
Vector.prototype.divide = function (f) { this.x /= f; this.y /= f; this.z /= f; };
Vector.prototype.getXYAngle = function () { return Math.atan2(this.y, this.x); };
Vector.prototype.getZAngle = function () { return Math.acos(clamp(-1, this.z / (this.getLength() || 1), 1)); };
Vector.prototype.getMinimum = function () { return Math.min(this.x, this.y, this.z); };
Vector.prototype.getMaximum = function () { return Math.max(this.x, this.y, this.z); };
Vector.prototype.toString = function () { return "(" + this.x + ", " + this.y + ", " + this.z + ")"; };
function __vector(v) { return new Vector(v.x, v.y, v.z); }
function __Vector_sum(a, b) { return new Vector(a.x + b.x, a.y + b.y, a.z + b.z); };
function __Vector_diff(a, b) { return new Vector(a.x - b.x, a.y - b.y, a.z - b.z); };
function __Vector_product(a, f) { return new Vector(a.x * f, a.y * f, a.z * f); };
function __Vector_dot(a, b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
function __Vector_cross(a, b) {
  return new Vector(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
};
function __Vector_getDistance(a, b) { return Vector.diff(a, b).getLength(); };
function __Vector_getDistance2(a, b) { return Vector.diff(a, b).getLength2(); };
function __Vector_getAngle(a, b) {
  var l = a.getLength() * b.getLength();
  return l == 0 ? 0 : Math.acos(clamp(-1, Vector.dot(a, b) / l, 1));
};
function __Vector_lerp(a, b, t) { return new Vector(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t); };

function isSameDirection(a, b) {
  var l = a.getLength() * b.getLength();
  return l > 0 && Math.abs(Vector.dot(a, b) / l - 1) < 1e-9;
}

// A 3x3 matrix: rows as vectors. The declarations' constructors: none
// (the identity), a scale (the identity times it), three vectors, an
// array of three, and an axis and an angle (the rotation by the angle
// about the axis, right-handed, as `Matrix.getXRotation` turns about X).
function Matrix(a, b, c) {
  var rows;
  if (a === undefined) {
    rows = [new Vector(1, 0, 0), new Vector(0, 1, 0), new Vector(0, 0, 1)];
  } else if (typeof a == "number" && b === undefined) {
    rows = [new Vector(a, 0, 0), new Vector(0, a, 0), new Vector(0, 0, a)];
  } else if (typeof b == "number") {
    var k = __vector(a).getNormalized();
    var cos = Math.cos(b), sin = Math.sin(b), t = 1 - cos;
    rows = [
      new Vector(cos + k.x * k.x * t, k.x * k.y * t - k.z * sin, k.x * k.z * t + k.y * sin),
      new Vector(k.y * k.x * t + k.z * sin, cos + k.y * k.y * t, k.y * k.z * t - k.x * sin),
      new Vector(k.z * k.x * t - k.y * sin, k.z * k.y * t + k.x * sin, cos + k.z * k.z * t)
    ];
  } else if (b === undefined) {
    rows = [__vector(a[0]), __vector(a[1]), __vector(a[2])];
  } else {
    rows = [__vector(a), __vector(b), __vector(c)];
  }
  this.rows = rows;
  __derive(this);
  this.getEulerZYX = function () { return __vector(this.eulerZYX_R); };
  this.getElement = function (row, column) { return this.rows[row].getCoordinate(column); };
  // Each change of an element keeps the properties read from them
  // (`forward`, `right`, `up`, `eulerZYX_R`) those of the matrix as it is.
  this.setElement = function (row, column, value) {
    this.rows[row].setCoordinate(column, value);
    __derive(this);
  };
  this.getRow = function (row) { return __vector(this.rows[row]); };
  this.setRow = function (row, value) {
    this.rows[row] = __vector(value);
    __derive(this);
  };
  this.getColumn = function (column) {
    return new Vector(this.rows[0].getCoordinate(column), this.rows[1].getCoordinate(column), this.rows[2].getCoordinate(column));
  };
  this.setColumn = function (column, value) {
    for (var i = 0; i < 3; ++i) { this.rows[i].setCoordinate(column, value.getCoordinate(i)); }
    __derive(this);
  };
  this.getForward = function () { return this.getColumn(2); };
  this.getRight = function () { return this.getColumn(0); };
  this.getUp = function () { return this.getColumn(1); };
  this.setForward = function (v) { this.setColumn(2, v); };
  this.setRight = function (v) { this.setColumn(0, v); };
  this.setUp = function (v) { this.setColumn(1, v); };
  this.transpose = function () {
    this.rows = this.getTransposed().rows;
    __derive(this);
  };
  this.negate = function () {
    for (var i = 0; i < 3; ++i) { this.rows[i] = this.rows[i].getNegated(); }
    __derive(this);
  };
  this.getNegated = function () { return new Matrix(this.rows[0].getNegated(), this.rows[1].getNegated(), this.rows[2].getNegated()); };
  this.add = function (m) {
    for (var i = 0; i < 3; ++i) { this.rows[i] = Vector.sum(this.rows[i], m.rows[i]); }
    __derive(this);
  };
  this.subtract = function (m) {
    for (var i = 0; i < 3; ++i) { this.rows[i] = Vector.diff(this.rows[i], m.rows[i]); }
    __derive(this);
  };
  this.isIdentity = function () {
    for (var i = 0; i < 3; ++i) {
      for (var j = 0; j < 3; ++j) {
        if (Math.abs(this.getElement(i, j) - (i == j ? 1 : 0)) > 1e-9) { return false; }
      }
    }
    return true;
  };
  this.isZero = function () {
    for (var i = 0; i < 3; ++i) {
      if (!this.rows[i].isZero()) { return false; }
    }
    return true;
  };
  this.getTransposed = function () { return new Matrix(this.getColumn(0), this.getColumn(1), this.getColumn(2)); };
  this.multiply = function (v) {
    if (typeof v == "number") {
      return new Matrix(Vector.product(this.rows[0], v), Vector.product(this.rows[1], v), Vector.product(this.rows[2], v));
    }
    if (v.rows !== undefined) {
      var t = v.getTransposed();
      var r = [];
      for (var i = 0; i < 3; ++i) {
        r.push(new Vector(Vector.dot(this.rows[i], t.rows[0]), Vector.dot(this.rows[i], t.rows[1]), Vector.dot(this.rows[i], t.rows[2])));
      }
      return new Matrix(r[0], r[1], r[2]);
    }
    return new Vector(Vector.dot(this.rows[0], v), Vector.dot(this.rows[1], v), Vector.dot(this.rows[2], v));
  };
  // A rotation's angles in a convention: 0 for the identity (the work
  // plane of every section postc posts), in every convention; another
  // matrix stops the post with the function named (docs/fusion.md,
  // choice 39).
  this.getEuler = function (convention) { return __identityAngles(this, "getEuler"); };
  this.getEuler2 = function (convention) { return __identityAngles(this, "getEuler2"); };
  this.getEulerZXZ = function () { return __identityAngles(this, "getEulerZXZ"); };
  this.getEulerZYZ = function () { return __identityAngles(this, "getEulerZYZ"); };
  this.getEulerXYZ = function () { return __identityAngles(this, "getEulerXYZ"); };
  this.getTurnAndTilt = function (primary, secondary) { return __identityAngles(this, "getTurnAndTilt"); };
  this.getTiltAndTilt = function (primary, secondary) { return __identityAngles(this, "getTiltAndTilt"); };
}
// The properties read from a matrix's elements: its columns (`right`,
// `up`, `forward`) and its ZYX Euler angles in radians, the matrix being
// the rotation about X by `x`, then about Y by `y`, then about Z by `z`
// (`Matrix.getXYZRotation`).
function __derive(m) {
  var rows = m.rows;
  m.forward = new Vector(rows[0].z, rows[1].z, rows[2].z);
  m.right = new Vector(rows[0].x, rows[1].x, rows[2].x);
  m.up = new Vector(rows[0].y, rows[1].y, rows[2].y);
  m.eulerZYX_R = new Vector(Math.atan2(rows[2].y, rows[2].z), -Math.asin(clamp(-1, rows[2].x, 1)), Math.atan2(rows[1].x, rows[0].x));
}
function __identityAngles(m, name) {
  if (!m.isIdentity()) {
    error("postc does not compute a rotation's angles in Fusion's conventions yet: `Matrix." + name +
      "` of a matrix other than the identity (docs/fusion.md, choice 39)");
  }
  return new Vector(0, 0, 0);
}
function __Matrix_getIdentity() { return new Matrix(); };
function __Matrix_getXRotation(a) {
  return new Matrix(new Vector(1, 0, 0), new Vector(0, Math.cos(a), -Math.sin(a)), new Vector(0, Math.sin(a), Math.cos(a)));
};
function __Matrix_getYRotation(a) {
  return new Matrix(new Vector(Math.cos(a), 0, Math.sin(a)), new Vector(0, 1, 0), new Vector(-Math.sin(a), 0, Math.cos(a)));
};
function __Matrix_getZRotation(a) {
  return new Matrix(new Vector(Math.cos(a), -Math.sin(a), 0), new Vector(Math.sin(a), Math.cos(a), 0), new Vector(0, 0, 1));
};
// The rotation of the XYZ Euler angles `abc`: about X by `abc.x` first,
// then about Y, then about Z.
function __Matrix_getXYZRotation(abc) {
  return __Matrix_getZRotation(abc.z).multiply(__Matrix_getYRotation(abc.y)).multiply(__Matrix_getXRotation(abc.x));
};
function __Matrix_getAxisRotation(axis, a) { return new Matrix(); };
function __Matrix_getOrientationFromDirection(v) { return new Matrix(); };

// ---- Formats and output variables ----

// The text of `value` under a format's specifiers: scaled, offset,
// rounded half away from zero to `decimals`, trailing zeros trimmed
// (`trim`), the point kept only with `forceDecimal`, the integer part
// zero-padded to `width` (`zeropad`), `+` for positive values with
// `forceSign`, the lead zero dropped with `trimLeadZero`. The primitive
// `__postc_formatNumber(spec, value)` is native in postc (runtime
// `interp/host_text.rs`); it gives `undefined` for a value that is not
// a finite number, which is an error at the post's call.
function __notFinite(value) {
  error(localize("Cannot format a value that is not a finite number") + ": " + value);
}

function __spec(s) {
  if (s === undefined) { s = {}; }
  function pick(name, otherwise) { return s[name] === undefined ? otherwise : s[name]; }
  return {
    prefix: pick("prefix", ""),
    suffix: pick("suffix", ""),
    decimals: pick("decimals", 6),
    forceDecimal: pick("forceDecimal", false),
    forceSign: pick("forceSign", false),
    zeropad: pick("zeropad", false),
    width: pick("width", 0),
    trim: pick("trim", true),
    trimLeadZero: pick("trimLeadZero", false),
    scale: pick("scale", 1),
    offset: pick("offset", 0),
    cyclicLimit: pick("cyclicLimit", undefined),
    cyclicSign: pick("cyclicSign", 0),
    decimalSymbol: pick("separator", pick("decimalSymbol", ".")),
    type: pick("type", FORMAT_REAL)
  };
}

function FormatNumber(specifiers) {
  var spec = __spec(specifiers);
  this.spec = spec;
  this.format = function (value) {
    var text = __postc_formatNumber(spec, value);
    if (text === undefined) { __notFinite(value); }
    return text;
  };
  this.getResultingValue = function (value) {
    var f = Math.pow(10, spec.decimals);
    var v = value * spec.scale + spec.offset;
    return (v < 0 ? -1 : 1) * Math.floor(Math.abs(v) * f + 0.5) / f;
  };
  this.getError = function (value) { return this.getResultingValue(value) - value; };
  this.isSignificant = function (value) { return this.getResultingValue(value) != 0; };
  this.areDifferent = function (a, b) { return this.getResultingValue(a) != this.getResultingValue(b); };
  this.getMinimumValue = function () { return Math.pow(10, -spec.decimals); };
  this.getDecimalSymbol = function () { return spec.decimalSymbol; };
  this.setDecimalSymbol = function (v) { spec.decimalSymbol = v; };
  this.getZeroPad = function () { return spec.zeropad; };
  this.setZeroPad = function (v) { spec.zeropad = v; };
  this.getForceSign = function () { return spec.forceSign; };
  this.setForceSign = function (v) { spec.forceSign = v; };
  this.getForceDecimal = function () { return spec.forceDecimal; };
  this.setForceDecimal = function (v) { spec.forceDecimal = v; };
  this.getWidth = function () { return spec.width; };
  this.setWidth = function (v) { spec.width = v; };
  this.getNumberOfDecimals = function () { return spec.decimals; };
  this.setNumberOfDecimals = function (v) { spec.decimals = v; };
  this.getTrimZeroDecimals = function () { return spec.trim; };
  this.setTrimZeroDecimals = function (v) { spec.trim = v; };
  this.getTrimLeadZero = function () { return spec.trimLeadZero; };
  this.setTrimLeadZero = function (v) { spec.trimLeadZero = v; };
  this.getScale = function () { return spec.scale; };
  this.setScale = function (v) { spec.scale = v; };
  this.getOffset = function () { return spec.offset; };
  this.setOffset = function (v) { spec.offset = v; };
  this.getPrefix = function () { return spec.prefix; };
  this.setPrefix = function (v) { spec.prefix = v; };
  this.getSuffix = function () { return spec.suffix; };
  this.setSuffix = function (v) { spec.suffix = v; };
  this.getCyclicLimit = function () { return spec.cyclicLimit; };
  this.getCyclicSign = function () { return spec.cyclicSign; };
  this.setCyclicMapping = function (limit, sign) { spec.cyclicLimit = limit; spec.cyclicSign = sign; };
  this.remap = function (value) { return value; };
}
function createFormat(specifiers) { return new FormatNumber(specifiers); }
// The function every format's `format` is: an output whose format's is
// this one prints through postc's native `__postc_formatOutput` (runtime
// `interp/host_text.rs`), which gives `undefined` where the JavaScript
// below it has more to do.
var __formatMethod = new FormatNumber().format;

function __prefixed(s, name) { return (s === undefined || s[name] === undefined) ? "" : s[name]; }

// `createVariable`: prints when the formatted value changes (or always,
// with `force`), with the variable's prefix before the format's text.
function Variable(specifiers, format) {
  this.prefix = __prefixed(specifiers, "prefix");
  this.force = specifiers !== undefined && specifiers.force === true;
  this.onchange = specifiers === undefined ? undefined : specifiers.onchange;
  this.nonzero = false;
  this.formatter = format;
  this.last = undefined;
  this.current = undefined;
  this.enabled = true;
  this.format = function (value) {
    var printed = __postc_formatOutput(this, value, __formatMethod, false);
    if (printed !== undefined) { return printed; }
    if (!this.enabled) { return ""; }
    var text = this.formatter.format(value);
    // The first value a variable prints is a change too (docs/fusion.md).
    var changed = text !== this.last;
    // `CONTROL_NONZERO` prints every value that is not zero, changed or not.
    if (this.nonzero) {
      if (!this.formatter.areDifferent(value, 0)) { return ""; }
    } else if (!changed && !this.force) { return ""; }
    this.last = text;
    this.current = value;
    if (changed && this.onchange !== undefined) { this.onchange(); }
    return this.prefix + text;
  };
  this.getPrefix = function () { return this.prefix; };
  this.setPrefix = function (p) { this.prefix = p; };
  this.getFormat = function () { return this.formatter; };
  this.setFormat = function (f) { this.formatter = f; };
  this.reset = function () { this.last = undefined; };
  this.disable = function () { this.enabled = false; };
  this.enable = function () { this.enabled = true; };
  this.isEnabled = function () { return this.enabled; };
  this.getCurrent = function () { return this.current; };
  this.setCurrent = function (value) { this.current = value; this.last = this.formatter.format(value); };
}
function createVariable(specifiers, format) { return new Variable(specifiers, format); }
function createOutputVariable(specifiers, format) {
  var v = new Variable(specifiers, format);
  if (specifiers !== undefined && specifiers.control == CONTROL_FORCE) { v.force = true; }
  if (specifiers !== undefined && specifiers.control == CONTROL_NONZERO) { v.nonzero = true; }
  return v;
}

// `createModal`: like a variable; a modal code's value may be text.
function Modal(specifiers, format) {
  this.prefix = __prefixed(specifiers, "prefix");
  this.suffix = __prefixed(specifiers, "suffix");
  this.force = specifiers !== undefined && specifiers.force === true;
  this.onchange = specifiers === undefined ? undefined : specifiers.onchange;
  this.formatter = format;
  this.last = undefined;
  this.current = undefined;
  this.format = function (value) {
    var printed = __postc_formatOutput(this, value, __formatMethod, true);
    if (printed !== undefined) { return printed; }
    var text = (typeof value == "number" && this.formatter !== undefined) ? this.formatter.format(value) : String(value);
    var changed = text !== this.last;
    if (!changed && !this.force) { return ""; }
    this.last = text;
    this.current = value;
    if (changed && this.onchange !== undefined) { this.onchange(); }
    return this.prefix + text + this.suffix;
  };
  this.getPrefix = function () { return this.prefix; };
  this.setPrefix = function (p) { this.prefix = p; };
  this.getSuffix = function () { return this.suffix; };
  this.setSuffix = function (p) { this.suffix = p; };
  this.reset = function () { this.last = undefined; };
  this.getCurrent = function () { return this.current; };
  this.disable = function () { this.force = false; };
}
function createModal(specifiers, format) { return new Modal(specifiers, format); }

// `createReferenceVariable`: prints when the value differs from the
// reference given with it (or always, with `force`).
function ReferenceVariable(specifiers, format) {
  this.prefix = __prefixed(specifiers, "prefix");
  this.force = specifiers !== undefined && specifiers.force === true;
  this.formatter = format;
  this.enabled = true;
  this.format = function (value, reference) {
    if (!this.enabled) { return ""; }
    if (!this.force && !this.formatter.areDifferent(value, reference)) { return ""; }
    return this.prefix + this.formatter.format(value);
  };
  this.getPrefix = function () { return this.prefix; };
  this.setPrefix = function (p) { this.prefix = p; };
  this.disable = function () { this.enabled = false; };
  this.enable = function () { this.enabled = true; };
}
function createReferenceVariable(specifiers, format) { return new ReferenceVariable(specifiers, format); }

// `createIncrementalVariable`: prints the change from the last value.
// `reset()` makes the next value print even when it is no change; the
// last value stays the base of the next change (docs/fusion.md).
function IncrementalVariable(specifiers, format) {
  this.prefix = __prefixed(specifiers, "prefix");
  this.force = specifiers !== undefined && specifiers.force === true;
  this.formatter = format;
  this.current = undefined;
  this.forced = false;
  this.enabled = true;
  this.format = function (value) {
    if (!this.enabled) { return ""; }
    var previous = this.current === undefined ? 0 : this.current;
    this.current = value;
    var forced = this.forced;
    this.forced = false;
    if (!this.force && !forced && !this.formatter.areDifferent(value, previous)) { return ""; }
    return this.prefix + this.formatter.format(value - previous);
  };
  this.getPrefix = function () { return this.prefix; };
  this.setPrefix = function (p) { this.prefix = p; };
  this.reset = function () { this.forced = true; };
  this.disable = function () { this.enabled = false; };
  this.getCurrent = function () { return this.current; };
}
function createIncrementalVariable(specifiers, format) { return new IncrementalVariable(specifiers, format); }

// ---- Writing ----
var __wordSeparator = " ";
function setWordSeparator(separator) { __wordSeparator = separator; }
function getWordSeparator() { return __wordSeparator; }
// The code page the program is written in (docs/fusion.md, choice 38):
// postc writes Windows-1252 for a post whose every `setCodePage` names
// "ansi", UTF-8 otherwise.
var __codePage = "";
function setCodePage(name) { __codePage = String(name).toLowerCase(); }
function getCodePage() { return __codePage == "utf-8" ? 65001 : (__codePage == "ascii" ? 20127 : 1252); }
// The end-of-line marker every later line ends with (docs/fusion.md,
// choice 5).
function setEOL(eol) { EOL = String(eol); }
var __redirect = undefined;
// Text `write` gave that no line ending has closed yet.
var __partial = "";
function writeln(text) {
  if (__redirect !== undefined) {
    __redirect.text += text + EOL;
  } else {
    __postc_writeln(__partial + text, EOL);
    __partial = "";
  }
}
function write(text) {
  if (__redirect !== undefined) {
    __redirect.text += text;
  } else {
    __partial += String(text);
  }
}
function redirectToBuffer() { __redirect = { text: "" }; }
function getRedirectionBuffer() { return __redirect === undefined ? "" : __redirect.text; }
function closeRedirection() { __redirect = undefined; }
function isRedirecting() { return __redirect !== undefined; }

// The words of a block: texts and arrays of texts (an `arguments`
// object too), the empty ones left out, joined by the word separator.
// The primitive `__postc_words(list, separator, start)` (the words of
// the list from `start`, joined) is native in postc (runtime
// `interp/host_text.rs`).
function formatWords() {
  return __postc_words(arguments, __wordSeparator, 0);
}
function writeWords() {
  var text = __postc_words(arguments, __wordSeparator, 0);
  if (text != "") { writeln(text); }
}
// The first word only when a word follows it.
function writeWords2(first) {
  var text = __postc_words(arguments, __wordSeparator, 1);
  if (text != "") { writeln(__postc_words([first, text], __wordSeparator, 0)); }
}
function subst(text) {
  var result = String(text);
  for (var i = 1; i < arguments.length; ++i) {
    result = result.split("%" + i).join(String(arguments[i]));
  }
  return result;
}
function localize(text) { return text; }
function filterText(text, keep) {
  var result = "";
  var s = String(text);
  for (var i = 0; i < s.length; ++i) {
    if (keep.indexOf(s.charAt(i)) >= 0) { result += s.charAt(i); }
  }
  return result;
}
function translateText(text, from, to) {
  var result = "";
  var s = String(text);
  for (var i = 0; i < s.length; ++i) {
    var k = from.indexOf(s.charAt(i));
    result += k >= 0 ? to.charAt(k) : s.charAt(i);
  }
  return result;
}
function conditional(condition, value) { return condition ? value : ""; }
function isSafeText(text, permitted) { return filterText(text, permitted) == text; }
function isTextSupported(text) { return true; }

// ---- Messages ----
function error(message) { throw new Error(message); }
function warning(message) {}
// A dialog in Fusion when it may interact; a batch run has none.
function alert(title, description) {}
function isInteractionAllowed() { return false; }
// postc runs no machine simulation: there is no stream to write.
function getSimulationStreamPath() { return ""; }
function getRadiusCompensation() { return radiusCompensation; }
var __warnedOnce = {};
function warningOnce(message, id) { __warnedOnce[id] = true; }
function log(message) {}
function debug(message) {}
function validate(condition, message) { if (!condition) { error(message); } }

// ---- Properties ----
// A property is named by its name or given as its object
// (`getProperty(properties.method)`, as newer declarations type it:
// `getProperty(property: ScriptObject, defaultValue)`): the name of the
// post's property that is that object.
function __propertyName(property) {
  if (property !== null && typeof property == "object") {
    for (var k in properties) {
      if (properties[k] === property) { return k; }
    }
  }
  return property;
}
// A property by name is postc's native `__postc_property` (runtime
// `interp/host_text.rs`): the three lines below.
function getProperty(name, otherwise) {
  if (typeof name == "string") { return __postc_property(properties, name, otherwise); }
  name = __propertyName(name);
  var p = properties[name];
  if (p === undefined) { return otherwise; }
  if (p !== null && typeof p == "object" && p.value !== undefined) { return p.value; }
  return p;
}
function setProperty(name, value) {
  name = __propertyName(name);
  var p = properties[name];
  if (p !== null && typeof p == "object" && p.value !== undefined) { p.value = value; } else { properties[name] = value; }
}

// ---- The job: sections, tools, parameters ----
var __sections = [];
var __section = undefined;
var __position = new Vector(0, 0, 0);
var __closing = false;
var __circular = undefined;
var __spindle = 0;
var __coolantOn = false;

function Tool(number, diameter, name) {
  this.number = number;
  this.turret = 0;
  this.diameter = diameter;
  this.cornerRadius = 0;
  this.taperAngle = 0;
  this.fluteLength = 0;
  this.shoulderLength = 0;
  this.shaftDiameter = diameter;
  this.bodyLength = 0;
  this.overallLength = 0;
  this.numberOfFlutes = 2;
  this.threadPitch = 0;
  this.tipAngle = 0;
  // Newer engines than the declarations give it (a chamfer mill's small
  // diameter); postc's tools have none.
  this.tipDiameter = 0;
  this.type = TOOL_MILLING_END_FLAT;
  this.material = MATERIAL_CARBIDE;
  this.comment = name;
  this.description = name;
  this.vendor = "";
  this.productId = "";
  this.holderNumber = 0;
  this.holderDescription = "";
  this.holderComment = "";
  this.holderVendor = "";
  this.holderProductId = "";
  this.holderLength = 0;
  this.lengthOffset = number;
  this.diameterOffset = number;
  this.compensationOffset = number;
  this.spindleRPM = 0;
  this.rampingSpindleRPM = 0;
  this.surfaceSpeed = 0;
  this.maximumSpindleSpeed = 0;
  this.clockwise = true;
  this.coolant = COOLANT_OFF;
  this.breakControl = false;
  this.manualToolChange = false;
  this.liveTool = false;
  this.jetTool = false;
  this.isJetTool = function () { return this.jetTool; };
  // A lathe's turning tool (the toolpath's `turning` tool; docs/fusion.md,
  // "Turning"): its insert's nose radius is half the toolpath's diameter;
  // the other insert sizes the toolpath does not give are 0, as a
  // milling tool's unknown sizes are (choice 12).
  this.turningTool = false;
  this.isTurningTool = function () { return this.turningTool; };
  this.spindleMode = SPINDLE_CONSTANT_SPINDLE_SPEED;
  this.noseRadius = 0;
  this.inscribedCircleDiameter = 0;
  this.edgeLength = 0;
  this.reliefAngle = 0;
  this.thickness = 0;
  this.grooveWidth = 0;
  this.crossSection = "";
  this.tolerance = "";
  this.pitch = 0;
  this.hand = "";
  this.clamping = "";
  this.boringBarOrientation = 0;
  this.isDrill = function () { return this.type == TOOL_DRILL; };
  this.isLiveTool = function () { return this.liveTool; };
  this.getNumber = function () { return this.number; };
  this.getToolId = function () { return "T" + this.number + " D" + this.diameter + " " + this.description; };
  this.getDiameter = function () { return this.diameter; };
  this.getCornerRadius = function () { return this.cornerRadius; };
  this.getTaperAngle = function () { return this.taperAngle; };
  this.getFluteLength = function () { return this.fluteLength; };
  this.getBodyLength = function () { return this.bodyLength; };
  this.getHolderLength = function () { return this.holderLength; };
  this.getThreadPitch = function () { return this.threadPitch; };
  this.getTappingFeedrate = function () { return this.threadPitch * this.spindleRPM; };
  this.getDescription = function () { return this.description; };
  this.getComment = function () { return this.comment; };
  this.getType = function () { return this.type; };
  this.getSpindleMode = function () { return this.spindleMode; };
  this.getManualToolChange = function () { return this.manualToolChange; };
  this.getBreakControl = function () { return this.breakControl; };
  this.getLengthOffset = function () { return this.lengthOffset; };
  this.getDiameterOffset = function () { return this.diameterOffset; };
  this.getCoolant = function () { return this.coolant; };
  this.getCoolants = function () { return [this.coolant]; };
  this.getHolder = function () { return undefined; };
  this.getShaft = function () { return undefined; };
  this.getSpindleRPM = function () { return this.spindleRPM; };
  this.isClockwise = function () { return this.clockwise; };
}

function __Section(id, theTool, name) {
  this.id = id;
  this.tool = theTool;
  this.name = name;
  this.workOffset = 0;
  this.wcs = "G54";
  this.workPlane = new Matrix();
  this.workOrigin = new Vector(0, 0, 0);
  this.spindle = SPINDLE_PRIMARY;
  this.feedMode = FEED_PER_MINUTE;
  this.strategy = "";
  this.type = TYPE_MILLING;
  this.quality = 0;
  this.jetMode = JET_MODE_THROUGH;
  this.polarMode = 0;
  this.machiningType = 0;
  this.probeWorkOffset = 0;
  this.partCatcher = false;
  this.tailstock = false;
  this.toolOrientation = 0;
  this.initialPosition = undefined;
  this.finalPosition = undefined;
  this.zRange = undefined;
  this.parameters = {};
  this.getId = function () { return this.id; };
  this.getTool = function () { return this.tool; };
  this.getType = function () { return this.type; };
  this.getParameter = function (name, otherwise) {
    var v = this.parameters[name];
    return v === undefined ? otherwise : v;
  };
  this.hasParameter = function (name) { return this.parameters[name] !== undefined; };
  this.getInitialPosition = function () { return __vector(this.initialPosition === undefined ? __position : this.initialPosition); };
  this.getFinalPosition = function () { return __vector(this.finalPosition === undefined ? __position : this.finalPosition); };
  this.getGlobalInitialToolAxis = function () { return new Vector(0, 0, 1); };
  this.getGlobalFinalToolAxis = function () { return new Vector(0, 0, 1); };
  this.getInitialToolAxis = function () { return new Vector(0, 0, 1); };
  this.getFinalToolAxis = function () { return new Vector(0, 0, 1); };
  this.getInitialToolAxisABC = function () { return new Vector(0, 0, 0); };
  this.getFinalToolAxisABC = function () { return new Vector(0, 0, 0); };
  this.getGlobalZRange = function () {
    return this.zRange === undefined ? new Range(__position.z, __position.z) : new Range(this.zRange.minimum, this.zRange.maximum);
  };
  this.getGlobalRange = function (direction) { return this.getGlobalZRange(); };
  this.getBoundingBox = function () { return { lower: new Vector(0, 0, 0), upper: new Vector(0, 0, 0) }; };
  this.getGlobalBoundingBox = function () { return this.getBoundingBox(); };
  this.getPatternId = function () { return 0; };
  this.getInternalPatternId = function () { return 0; };
  this.isPatterned = function () { return false; };
  this.getNumberOfPatternInstances = function () { return 1; };
  this.getForceToolChange = function () { return false; };
  this.isOptional = function () { return false; };
  this.isMultiAxis = function () { return false; };
  this.isOptimizedForMachine = function () { return false; };
  this.getOptimizedTCPMode = function () { return TCP_MODE_OFF; };
  this.optimizeMachineAnglesByMachine = function (machine, mode) {};
  this.optimize = function () {};
  this.getABCByPreference = function () { return new Vector(0, 0, 0); };
  // The section's drilling cycles as far as postc has read them: those
  // before its first move and every one posted since (docs/fusion.md,
  // choice 19).
  // With the job read ahead, the section's cycles are known before they
  // come: their number, their holes, the type of the first.
  this.cycles = [];
  this.plannedCycles = 0;
  this.plannedCyclePoints = 0;
  this.plannedCycle = "";
  this.hasAnyCycle = function () { return this.getNumberOfCycles() > 0; };
  this.hasCycle = function (type) {
    for (var i = 0; i < this.cycles.length; ++i) {
      if (this.cycles[i].type == type) { return true; }
    }
    return this.plannedCycle == type;
  };
  this.getNumberOfCycles = function () { return Math.max(this.cycles.length, this.plannedCycles); };
  this.getNumberOfCyclesWithId = function (type) {
    var n = 0;
    for (var i = 0; i < this.cycles.length; ++i) {
      if (this.cycles[i].type == type) { ++n; }
    }
    return n;
  };
  this.getCycleId = function (i) { return this.cycles[i].type; };
  this.getNumberOfCyclePoints = function () {
    var n = 0;
    for (var i = 0; i < this.cycles.length; ++i) { n += this.cycles[i].points.length; }
    return Math.max(n, this.plannedCyclePoints);
  };
  this.getFirstCycle = function () { return this.cycles.length > 0 ? this.cycles[0].type : this.plannedCycle; };
  this.doesStartWithCycle = function (type) { return this.startsWithCycle && this.getFirstCycle() == type; };
  this.doesStartWithCycleIgnoringPositioning = function (type) { return this.doesStartWithCycle(type); };
  this.doesStrictCycle = function (type) {
    return this.startsWithCycle && this.getFirstCycle() == type && this.getNumberOfCyclesWithId(type) == this.cycles.length;
  };
  this.hasCycleParameter = function (i, name) { return i < this.cycles.length && this.cycles[i].cycle[name] !== undefined; };
  this.getCycleParameter = function (i, name) { return this.cycles[i].cycle[name]; };
  this.startsWithCycle = false;
  this.getMovements = function () { return 0; };
  this.getCycleTime = function () { return 0; };
  this.getMaximumFeedrate = function () { return 0; };
  this.getMaximumSpindleSpeed = function () { return this.tool.spindleRPM; };
  this.getInitialSpindleSpeed = function () { return this.tool.spindleRPM; };
  this.getRapidDistance = function () { return 0; };
  this.getCuttingDistance = function () { return 0; };
  this.getModelPlane = function () { return new Matrix(); };
  this.getModelOrigin = function () { return new Vector(0, 0, 0); };
  this.getWorkOrigin = function () { return new Vector(0, 0, 0); };
  this.getWorkOffset = function () { return this.workOffset; };
  this.getDynamicWorkOffset = function () { return 0; };
  this.hasDynamicWorkOffset = function () { return false; };
  this.getDynamicWCSPlane = function () { return new Matrix(); };
  this.getDynamicWCSOrigin = function () { return new Vector(0, 0, 0); };
  this.isZOriented = function () { return true; };
  // postc's sections cut along Z: never along X or Y.
  this.isXOriented = function () { return false; };
  this.isYOriented = function () { return false; };
  // Whether the section's first and last positions are known: its first
  // from the job's outline or once it has started, its last once it has
  // ended.
  this.hasWellDefinedPosition = function () {
    return this.initialPosition !== undefined && this.finalPosition !== undefined;
  };
  this.getPolarMode = function () { return 0; };
  this.getJetMode = function () { return this.jetMode; };
  this.getUnit = function () { return unit; };
  this.getSpindle = function () { return this.spindle; };
  this.getFeedMode = function () { return this.feedMode; };
  this.getToolOrientation = function () { return this.toolOrientation; };
  this.getTailstock = function () { return this.tailstock; };
  this.getPartCatcher = function () { return this.partCatcher; };
  this.isConnectionSection = function () { return false; };
  this.checkGroup = function (groups) { return false; };
  this.getProperty = function (name, otherwise) { return getProperty(name, otherwise); };
  this.doesToolpathFitWithinLimits = function (machine, position) { return true; };
}

// The job read ahead: `__outline` holds every section of the job as postc
// read it before posting (`JOB_OUTLINE`; empty when the toolpath is a
// stream read once), `__future` the sections made from it before they
// start (docs/fusion.md, choice 3).
var __outline = [];
var __future = [];
function getNumberOfSections() { return Math.max(__sections.length, __outline.length); }
function getSection(index) {
  if (index >= 0 && index < __sections.length) { return __sections[index]; }
  if (index >= 0 && index < __outline.length) { return __outlineSection(index); }
  error(subst(localize("postc knows section %1 only when it is posted: the toolpath is a stream it cannot read ahead"), index));
}
function getCurrentSectionId() { return __section === undefined ? -1 : __section.id; }
function isFirstSection() { return __section !== undefined && __section.id == 0; }
function isLastSection() {
  return __section !== undefined && __section.id == getNumberOfSections() - 1 && (__outline.length > 0 || __closing);
}
function getPreviousSection() { return (__section === undefined || __section.id == 0) ? undefined : __sections[__section.id - 1]; }
function hasNextSection() { return __section !== undefined && __section.id + 1 < getNumberOfSections(); }
function getNextSection() { return hasNextSection() ? getSection(__section.id + 1) : undefined; }
function getNextTool(number) {
  for (var i = (__section === undefined ? 0 : __section.id + 1); i < getNumberOfSections(); ++i) {
    var t = getSection(i).tool;
    if (t.number != number) { return t; }
  }
  return undefined;
}
function isToolChangeNeeded() {
  var previous = getPreviousSection();
  return previous === undefined || previous.tool.number != tool.number;
}
function isNewWorkPlane() { return isFirstSection(); }
function isNewWorkOffset() {
  var previous = getPreviousSection();
  return previous === undefined || previous.workOffset != currentSection.workOffset;
}
function getToolTable() {
  var tools = [];
  var seen = {};
  for (var i = 0; i < getNumberOfSections(); ++i) {
    var t = getSection(i).tool;
    if (!seen[t.number]) {
      seen[t.number] = true;
      tools.push(t);
    }
  }
  return {
    getNumberOfTools: function () { return tools.length; },
    getTool: function (i) { return tools[i]; }
  };
}
function getToolTypeName(type) {
  var names = ["unspecified", "drill", "center drill", "spot drill", "block drill", "flat end mill", "ball end mill",
    "bull nose end mill", "chamfer mill", "face mill", "slot mill", "radius mill", "dovetail mill", "tapered mill",
    "lollipop mill", "tap right hand", "tap left hand", "reamer", "boring bar", "counter bore", "counter sink", "holder",
    "general turning", "thread turning", "groove turning", "boring turning", "custom turning", "probe", "wire",
    "water jet", "laser cutter", "welder", "grinder", "form mill", "plasma cutter", "marker", "thread mill"];
  return names[type] === undefined ? "unspecified" : names[type];
}

var __parameters = {};
function getParameter(name, otherwise) {
  if (__section !== undefined && __section.parameters[name] !== undefined) { return __section.parameters[name]; }
  var v = __parameters[name];
  return v === undefined ? otherwise : v;
}
function hasParameter(name) { return getParameter(name) !== undefined; }
function getGlobalParameter(name, otherwise) {
  var v = __parameters[name];
  return v === undefined ? otherwise : v;
}
function hasGlobalParameter(name) { return __parameters[name] !== undefined; }

function getCurrentPosition() { return __vector(__position); }
function setCurrentPosition(p) { __position = __vector(p); }
function getFramePosition(p) { return __vector(p); }
function getFrameDirection(d) { return __vector(d); }
function getCurrentDirection() { return new Vector(0, 0, 1); }
function getCurrentToolAxis() { return new Vector(0, 0, 1); }
function setCurrentABC(abc) {}
var __workpiece = undefined;
function getWorkpiece() {
  return __workpiece !== undefined ? __workpiece : { lower: new Vector(0, 0, 0), upper: new Vector(0, 0, 0) };
}
function isWorkpieceDefined() { return __workpiece !== undefined; }
function getMachineConfiguration() { return machineConfiguration; }
function setMachineConfiguration(machine) { machineConfiguration = machine; }
function optimizeMachineAngles() {}
function optimizeMachineAngles2(mode) {}
function setRotation(matrix) {}
function setTranslation(vector) {}
function cancelTransformation() {}
function getRotation() { return new Matrix(); }
function getTranslation() { return new Vector(0, 0, 0); }
function is3D() { return true; }
function isMultiAxis() { return false; }
function getHeaderVersion() { return ""; }
function getHeaderDate() { return ""; }
function getProduct() { return "postc"; }
function getVersion() { return ""; }
function getPlatform() { return ""; }
function getMaterialName() { return ""; }
function getGlobalZRange() { return currentSection.getGlobalZRange(); }
function isProbeOperation() { return false; }
// Newer engines than the declarations write the job's notes and an
// operation's (`writeSetupNotes()`, `writeSectionNotes()`: the global
// parameter `job-notes` and the section's `notes`) as comments through the
// post's `writeComment`, a line each, trimmed, blank lines left out.
// postc's toolpaths give neither parameter (the job's notes are
// `programComment`, choice 9): nothing is written (docs/fusion.md,
// choice 29).
function __writeNotes(text) {
  if (text === undefined || text === null || typeof writeComment != "function") { return; }
  var lines = String(text).split("\n");
  for (var i = 0; i < lines.length; ++i) {
    var comment = lines[i].trim();
    if (comment != "") { writeComment(comment); }
  }
}
function writeSetupNotes() { __writeNotes(getGlobalParameter("job-notes")); }
function writeSectionNotes() { __writeNotes(getParameter("notes")); }
// The cycle kinds of a section (newer engines than the declarations give
// them; Autodesk's reference: "isDrillingCycle(section, checkBoringCycles)",
// both arguments optional, the current section when none is given). A
// drilling cycle is a section of the `drill` strategy that is no milling
// cycle; a milling cycle is one with a cycle diameter (circular and thread
// milling), or, when boring cycles count, a shift: postc's cycles
// (docs/fusion.md, "The call order") have neither, so none is one.
function __cycleSection(args) {
  return (args.length > 0 && typeof args[0] == "object" && args[0] !== null) ? args[0] : currentSection;
}
function isDrillingCycle() {
  var s = __cycleSection(arguments);
  return s !== undefined && s.strategy == "drill";
}
function isMillingCycle() { return false; }
function isTappingCycle() {
  var s = __cycleSection(arguments);
  return s !== undefined && s.strategy == "drill" && String(s.getFirstCycle()).indexOf("tapping") >= 0;
}
function isInspectionOperation() { return false; }
function isDepositionOperation() { return false; }
function isMilling() { return currentSection === undefined || currentSection.type == TYPE_MILLING; }
function isTurning() { return currentSection !== undefined && currentSection.type == TYPE_TURNING; }
function isJet() { return currentSection !== undefined && currentSection.type == TYPE_JET; }
function skipRemainingSection() {}
// The names of the command constants, by value.
var __commandNames = {"-1": "COMMAND_INVALID", "0": "COMMAND_STOP", "1": "COMMAND_OPTIONAL_STOP", "2": "COMMAND_END", "3": "COMMAND_SPINDLE_CLOCKWISE", "4": "COMMAND_SPINDLE_COUNTERCLOCKWISE", "5": "COMMAND_START_SPINDLE", "6": "COMMAND_STOP_SPINDLE", "7": "COMMAND_ORIENTATE_SPINDLE", "8": "COMMAND_LOAD_TOOL", "9": "COMMAND_COOLANT_ON", "10": "COMMAND_COOLANT_OFF", "11": "COMMAND_ACTIVATE_SPEED_FEED_SYNCHRONIZATION", "12": "COMMAND_DEACTIVATE_SPEED_FEED_SYNCHRONIZATION", "13": "COMMAND_LOCK_MULTI_AXIS", "14": "COMMAND_UNLOCK_MULTI_AXIS", "15": "COMMAND_EXACT_STOP", "16": "COMMAND_START_CHIP_TRANSPORT", "17": "COMMAND_STOP_CHIP_TRANSPORT", "18": "COMMAND_OPEN_DOOR", "19": "COMMAND_CLOSE_DOOR", "20": "COMMAND_BREAK_CONTROL", "21": "COMMAND_TOOL_MEASURE", "22": "COMMAND_CALIBRATE", "23": "COMMAND_VERIFY", "24": "COMMAND_CLEAN", "25": "COMMAND_ALARM", "26": "COMMAND_ALERT", "27": "COMMAND_CHANGE_PALLET", "28": "COMMAND_POWER_ON", "29": "COMMAND_POWER_OFF", "30": "COMMAND_MAIN_CHUCK_OPEN", "31": "COMMAND_MAIN_CHUCK_CLOSE", "32": "COMMAND_SECONDARY_CHUCK_OPEN", "33": "COMMAND_SECONDARY_CHUCK_CLOSE", "34": "COMMAND_SECONDARY_SPINDLE_SYNCHRONIZATION_ACTIVATE", "35": "COMMAND_SECONDARY_SPINDLE_SYNCHRONIZATION_DEACTIVATE", "36": "COMMAND_SYNC_CHANNELS", "37": "COMMAND_PROBE_ON", "38": "COMMAND_PROBE_OFF", "44": "COMMAND_DISPLAY_MESSAGE", "45": "COMMAND_LIVE_ALIGNMENT"};
function getCommandStringId(command) {
  var name = __commandNames[command];
  return name === undefined ? "COMMAND_" + command : name;
}

// An axis a machine without rotary axes does not have.
function __Axis() {
  this.isEnabled = function () { return false; };
  this.getAxis = function () { return new Vector(0, 0, 0); };
  this.getCoordinate = function () { return -1; };
  this.getOffset = function () { return new Vector(0, 0, 0); };
  this.getRange = function () { return new Range(0, 0); };
  this.getPreference = function () { return 0; };
  this.getResolution = function () { return 0; };
  this.isCyclic = function () { return false; };
  this.isHead = function () { return false; };
  this.isTable = function () { return false; };
  this.isAggregate = function () { return false; };
  this.getEffectiveAxis = function () { return new Vector(0, 0, 0); };
  this.clamp = function (v) { return v; };
  this.remapToRange = function (v) { return v; };
  this.getMaximumFeed = function () { return 0; };
  this.getTCP = function () { return false; };
  this.isTCPEnabled = function () { return false; };
  __axisCommon(this);
}

// What every axis answers alike (Autodesk's declarations of `Axis`).
function __axisCommon(axis) {
  axis.getName = function () { return ["A", "B", "C"][axis.getCoordinate()] || ""; };
  axis.getActuator = function () { return 0; };
  axis.isLinear = function () { return false; };
  axis.isRotational = function () { return axis.isEnabled(); };
  axis.getDisplacement = function () { return 0; };
  axis.isSupported = function (value) { var r = axis.getRange(); return value >= r.getMinimum() && value <= r.getMaximum(); };
  axis.reduce = function (value) { return value; };
  axis.remapToRange2 = function (angle, current) { return axis.remapToRange(angle); };
  axis.clampToResolution = function (value) { return value; };
  axis.getResolutionError = function (value) { return 0; };
}

// A machine as postc's host has it: its rotary axes (`new
// MachineConfiguration(b, c)`, each made by `createAxis`) are what the
// post said they are, and the machine is a multi-axis one; their
// kinematics are not modelled: the machine angles of the top are 0, and
// those of another direction stop the post (docs/fusion.md, choice 39).
function MachineConfiguration() {
  this.axes = [];
  for (var a = 0; a < arguments.length; ++a) {
    if (arguments[a] instanceof __RotaryAxis) { this.axes.push(arguments[a]); }
  }
  this.rotary = this.axes.length > 0;
  this.vendor = "";
  this.model = "";
  this.description = "";
  this.isMultiAxisConfiguration = function () { return this.rotary; };
  this.isMachineCoordinate = function (i) { return this.getAxisByCoordinate(i).isEnabled(); };
  this.getNumberOfAxes = function () { return 3 + this.axes.length; };
  this.getAxisU = function () { return this.axes.length > 0 ? this.axes[0] : new __Axis(); };
  this.getAxisV = function () { return this.axes.length > 1 ? this.axes[1] : new __Axis(); };
  this.getAxisW = function () { return this.axes.length > 2 ? this.axes[2] : new __Axis(); };
  this.getAxisByCoordinate = function (coordinate) {
    for (var i = 0; i < this.axes.length; ++i) {
      if (this.axes[i].getCoordinate() == coordinate) { return this.axes[i]; }
    }
    return new __Axis();
  };
  this.getAxisX = function () { return new __Axis(); };
  this.getAxisY = function () { return new __Axis(); };
  this.getAxisZ = function () { return new __Axis(); };
  this.setAxisU = function (a) {};
  this.setAxisV = function (a) {};
  this.setAxisW = function (a) {};
  this.setAxisX = function (a) {};
  this.setAxisY = function (a) {};
  this.setAxisZ = function (a) {};
  this.setSafeRetractDistance = function (v) {};
  this.getSafeRetractDistance = function () { return 0; };
  this.setSafeRetractAndHomePositionsAvailable = function (v) {};
  this.setToolLength = function (v) {};
  this.getToolLength = function () { return 0; };
  this.setCenterPositionX = function (v) {};
  this.setCenterPositionY = function (v) {};
  this.setCenterPositionZ = function (v) {};
  this.setModel = function (v) { this.model = v; };
  // Settings a post gives the machine for Fusion's simulation and retracts:
  // kept, and given back by their getters.
  this.settings = {};
  var kept = ["SafeRetractFeedrate", "SafePlungeFeedrate", "MaximumFeedrate", "MaximumCuttingFeedrate", "Control",
    "RewindStockExpansion", "Wire", "Jet"];
  for (var i = 0; i < kept.length; ++i) {
    (function (machine, name) {
      machine["set" + name] = function (v) { machine.settings[name] = v; };
      machine["get" + name] = function () { return machine.settings[name] === undefined ? 0 : machine.settings[name]; };
    })(this, kept[i]);
  }
  this.getNumberOfTools = function () { return 0; };
  this.isABCSupported = function (abc) { return true; };
  this.getTableABC = function (abc) { return new Vector(0, 0, 0); };
  this.getOptimizedPosition = function (p, abc, tcp, options, verbose) { return __vector(p); };
  this.getABCByDirectionBoth = function (d) {
    __topOnly(this, d, "getABCByDirectionBoth");
    return [new Vector(0, 0, 0), new Vector(0, 0, 0)];
  };
  this.getRetractPosition = function () { return new Vector(0, 0, 0); };
  this.getMultiAxisFeedrateMode = function () { return FEED_FPM; };
  this.getMultiAxisFeedrateOutputTolerance = function () { return 0; };
  this.getMultiAxisFeedrateMaximum = function () { return 0; };
  this.getMultiAxisFeedrateInverseTimeUnits = function () { return INVERSE_MINUTES; };
  this.getMultiAxisFeedrateDPMType = function () { return DPM_STANDARD; };
  this.getMultiAxisFeedrateBpwRatio = function () { return 1; };
  // Whether the machine has rotary axes and every one is a head (a table).
  this.isHeadConfiguration = function () { return this.rotary && this.axes.every(function (a) { return a.isHead(); }); };
  this.isTableConfiguration = function () { return this.rotary && this.axes.every(function (a) { return a.isTable(); }); };
  this.getVendor = function () { return this.vendor; };
  this.getModel = function () { return this.model; };
  this.getDescription = function () { return this.description; };
  this.setVendor = function (v) { this.vendor = v; };
  this.setModel = function (v) { this.model = v; };
  this.setDescription = function (v) { this.description = v; };
  this.setVirtualTooltip = function (v) {};
  this.setMultiAxisFeedrate = function () {};
  this.setSingularity = function () {};
  this.getMaximumSpindleSpeed = function () { return 0; };
  this.setMaximumSpindleSpeed = function (v) {};
  this.getSpindleAxis = function () { return new Vector(0, 0, 1); };
  this.setSpindleAxis = function (v) {};
  this.getRemainingOrientation = function (abc, m) { return m; };
  this.getOptimizedDirection = function (axis, abc, reverse, tcp) { return new Vector(0, 0, 0); };
  this.getABCByPreference = function () { return new Vector(0, 0, 0); };
  this.getDirection = function (abc) { return new Vector(0, 0, 1); };
  this.getOrientation = function (abc) { return new Matrix(); };
  this.getABC = function (m) {
    __topOnly(this, m === undefined ? new Vector(0, 0, 1) : m.getForward(), "getABC");
    return new Vector(0, 0, 0);
  };
  this.getPreferredABC = function (abc) { return abc; };
  // The angles as the machine reaches them: given back as they are (postc
  // computes the top's, 0 on every axis, and does not check them against
  // the axes' ranges; docs/fusion.md, choice 39).
  this.remapABC = function (abc) { return __vector(abc); };
  this.remapToABC = function (abc, current) { return __vector(abc); };
  this.isSupported = function (m) { return true; };
  this.enableMachineRewinds = function () {};
  this.isReceived = function () { return false; };
  this.getModelUnit = function () { return unit; };
  // The home position and the retract plane a post gives the machine
  // (`setHomePositionX(v)`, `setRetractPlane(v)`): kept and given back;
  // `hasHomePositionX()` says whether the post gave one. Unset, they are 0.
  this.home = {};
  this.retractPlane = 0;
  this.setRetractPlane = function (v) { this.retractPlane = v; };
  this.getRetractPlane = function () { return this.retractPlane; };
  for (var h = 0; h < 3; ++h) {
    (function (machine, axis) {
      machine["setHomePosition" + axis] = function (v) { machine.home[axis] = v; };
      machine["getHomePosition" + axis] = function () { return machine.home[axis] === undefined ? 0 : machine.home[axis]; };
      machine["hasHomePosition" + axis] = function () { return machine.home[axis] !== undefined; };
    })(this, ["X", "Y", "Z"][h]);
  }
}
machineConfiguration = new MachineConfiguration();
function createAxis(specifiers) { return new __RotaryAxis(specifiers); }
// A rotary axis as `createAxis` specifies it (Autodesk's declarations:
// `coordinate` 0, 1, 2 for A, B, C; `table`, default true; `axis`, the
// direction it turns about; `offset`; `range` in degrees; `cyclic`;
// `preference`; `resolution`; `tcp`): what the post gave, in the
// declarations' units (angles in radians).
function __RotaryAxis(specifiers) {
  var s = specifiers || {};
  var vector = function (v, d) { return v === undefined ? d : (v instanceof Vector ? __vector(v) : new Vector(v[0], v[1], v[2])); };
  var coordinate = s.coordinate === undefined ? -1 : s.coordinate;
  var table = s.table === undefined ? true : !!s.table;
  var axis = vector(s.axis, new Vector(0, 0, 0));
  var offset = vector(s.offset, new Vector(0, 0, 0));
  var range = s.range === undefined ? null : new Range(s.range[0] * Math.PI / 180, s.range[1] * Math.PI / 180);
  var cyclic = !!s.cyclic;
  var preference = s.preference === undefined ? 0 : s.preference;
  var resolution = s.resolution === undefined ? 0 : s.resolution;
  var tcp = s.tcp === undefined ? true : !!s.tcp;
  this.isEnabled = function () { return true; };
  this.getAxis = function () { return __vector(axis); };
  this.getEffectiveAxis = function () { return __vector(axis); };
  this.getCoordinate = function () { return coordinate; };
  this.getOffset = function () { return __vector(offset); };
  this.getRange = function () { return range === null ? new Range(-1e9, 1e9) : range; };
  this.getPreference = function () { return preference; };
  this.getResolution = function () { return resolution; };
  this.isCyclic = function () { return cyclic; };
  this.isHead = function () { return !table; };
  this.isTable = function () { return table; };
  this.isAggregate = function () { return false; };
  this.clamp = function (v) { return range === null ? v : clamp(range.getMinimum(), v, range.getMaximum()); };
  this.remapToRange = function (v) { return v; };
  this.getMaximumFeed = function () { return 0; };
  this.getTCP = function () { return tcp; };
  this.isTCPEnabled = function () { return tcp; };
  __axisCommon(this);
}
// The machine angles of the top are 0 on any machine; those of another
// direction on a machine with rotary axes need its kinematics, which
// postc does not model: the post stops with the function named.
function __topOnly(machine, d, name) {
  if (machine.rotary && !(Math.abs(d.x) < 1e-9 && Math.abs(d.y) < 1e-9 && d.z > 0)) {
    error("postc does not model a machine's rotary kinematics yet: `MachineConfiguration." + name +
      "` of a direction other than the top's (docs/fusion.md, choice 39)");
  }
}

// ---- Circular moves (the current `onCircular` call) ----
function getCircularPlane() { return __circular.plane; }
function getCircularCenter() { return __vector(__circular.center); }
function getCircularStartRadius() { return __circular.radius; }
function getCircularRadius() { return __circular.radius; }
function getCircularSweep() { return __circular.sweep; }
function getCircularChordLength() { return Vector.diff(__circular.end, __circular.start).getLength(); }
// The axes of a circular plane: the first two span it (an arc turns
// from the first towards the second counter-clockwise, as G2/G3 under
// G17, G18 and G19), the third is its normal.
// One array a plane, made once: the host only reads them.
var __AXES_ZX = ["z", "x", "y"];
var __AXES_YZ = ["y", "z", "x"];
var __AXES_XY = ["x", "y", "z"];
function __planeAxes(plane) {
  return plane == PLANE_ZX ? __AXES_ZX : (plane == PLANE_YZ ? __AXES_YZ : __AXES_XY);
}
// A vector of the plane's coordinates (u, v, w).
function __fromPlane(plane, u, v, w) {
  var a = __planeAxes(plane);
  var p = {};
  p[a[0]] = u;
  p[a[1]] = v;
  p[a[2]] = w;
  return new Vector(p.x, p.y, p.z);
}
function getCircularNormal() {
  var n = __circular.clockwise ? -1 : 1;
  return __fromPlane(__circular.plane, 0, 0, n);
}
function getPositionU(u) {
  var c = __circular;
  var a = __planeAxes(c.plane);
  var angle = Math.atan2(c.start[a[1]] - c.center[a[1]], c.start[a[0]] - c.center[a[0]]) +
    (c.clockwise ? -1 : 1) * c.sweep * u;
  return __fromPlane(c.plane, c.center[a[0]] + c.radius * Math.cos(angle), c.center[a[1]] + c.radius * Math.sin(angle),
    c.start[a[2]] + (c.end[a[2]] - c.start[a[2]]) * u);
}
function isFullCircle() { return Math.abs(__circular.sweep - 2 * Math.PI) < 1e-9; }
function getHelicalDistance() {
  var w = __planeAxes(__circular.plane)[2];
  return __circular.end[w] - __circular.start[w];
}
function isHelical() { return Math.abs(getHelicalDistance()) > 1e-9; }
function isSpiral() { return false; }
function isClockwise() { return __circular.clockwise; }
function getHelicalOffset() { return __fromPlane(__circular.plane, 0, 0, getHelicalDistance()); }
function getHelicalPitch() {
  return __circular.sweep == 0 ? 0 : Math.abs(getHelicalDistance()) * 2 * Math.PI / __circular.sweep;
}
// The current arc as `onLinear` calls, each chord within `tol` of the arc.
function linearize(tol) {
  var c = __circular;
  var steps = 1;
  if (c.radius > tol) {
    var step = 2 * Math.acos(1 - tol / c.radius);
    steps = Math.max(1, Math.ceil(c.sweep / step));
  }
  for (var i = 1; i <= steps; ++i) {
    var p = i == steps ? c.end : getPositionU(i / steps);
    onLinear(p.x, p.y, p.z, c.feed);
    __position = __vector(p);
  }
}


// ---- JavaScript's globals the engine lacks ----
function isFinite(v) { var n = Number(v); return n - n == 0; }

// ---- Tables, colours, files ----
// Text with `${name}` fields that `substitute(values)` fills from an
// object's properties; a field with no property stays as written.
function Template(text) {
  this.text = String(text);
  this.substitute = function (values) {
    var out = "";
    var rest = this.text;
    for (;;) {
      var open = rest.indexOf("${");
      var close = open < 0 ? -1 : rest.indexOf("}", open + 2);
      if (close < 0) { return out + rest; }
      var key = rest.substring(open + 2, close);
      var v = values === undefined || values === null ? undefined : values[key];
      out += rest.substring(0, open) + (v === undefined ? rest.substring(open, close + 1) : v);
      rest = rest.substring(close + 1);
    }
  };
}

// Files beside the program: a post that opens one stops when it does.
function TextFile(path, write, encoding) { __unsupported("TextFile"); }
// Sending the program over the network (a post that uploads it to its
// machine): the same.
function XMLHttpRequest() { __unsupported("XMLHttpRequest"); }

// `new Table(values, {initial, force}, message)`: `lookup(id)` is the
// value for `id` (counted from `initial`), or an error with `message`.
function Table(values, specifiers, message) {
  this.values = values;
  this.initial = (specifiers !== undefined && specifiers.initial !== undefined) ? specifiers.initial : 0;
  this.message = message === undefined ? "Invalid index" : message;
  this.lookup = function (id) {
    var v = this.values[id - this.initial];
    if (v === undefined) { error(this.message); }
    return v;
  };
}
function Color(r, g, b) { this.r = r; this.g = g; this.b = b; }
function __FileSystem_getCombinedPath(a, b) { return a == "" ? b : a + PATH_SEPARATOR + b; }
function __FileSystem_getFilename(path) {
  var i = Math.max(path.lastIndexOf("/"), path.lastIndexOf("\\"));
  return path.substring(i + 1);
}
function __FileSystem_getFolderPath(path) {
  var i = Math.max(path.lastIndexOf("/"), path.lastIndexOf("\\"));
  return i < 0 ? "" : path.substring(0, i);
}
function __FileSystem_replaceExtension(path, ext) {
  var name = __FileSystem_getFilename(path);
  var dot = name.lastIndexOf(".");
  var stem = dot < 0 ? path : path.substring(0, path.length - name.length + dot);
  return stem + "." + ext;
}
function __FileSystem_isFile(path) { return false; }
function __FileSystem_isFolder(path) { return false; }
function __FileSystem_getFileSize(path) { __unsupported("FileSystem.getFileSize"); }
function __FileSystem_copyFile(a, b) { __unsupported("FileSystem.copyFile"); }
function __FileSystem_remove(path) { __unsupported("FileSystem.remove"); }
function __FileSystem_removeFolderRecursive(path) { __unsupported("FileSystem.removeFolderRecursive"); }
function __FileSystem_makeFolder(path) { __unsupported("FileSystem.makeFolder"); }
function __FileSystem_getTemporaryFolder() { __unsupported("FileSystem.getTemporaryFolder"); }
function __FileSystem_getTemporaryFile(prefix) { __unsupported("FileSystem.getTemporaryFile"); }
function FileSystem() {}
// `Math.random()`: the same numbers at every run, so that a program is
// reproducible (docs/fusion.md, choice 27): the Park-Miller generator
// (x' = 16807 x mod (2^31 - 1), every step exact in doubles) from 1.
var __randomState = 1;
function __Math_random() {
  __randomState = (__randomState * 16807) % 2147483647;
  return __randomState / 2147483647;
}
// `String.concat(s, ...)`: SpiderMonkey's generic of
// `String.prototype.concat` (its "String generics"), which Fusion's engine
// runs (docs/fusion.md, choice 40).
function __String_concat(s) {
  var text = String(s);
  for (var i = 1; i < arguments.length; ++i) { text += String(arguments[i]); }
  return text;
}
// `Array.isArray` as a value (`var isArray = Array.isArray || ...`); a call
// `Array.isArray(v)` is JavaScript's own.
function __Array_isArray(v) { return Object.prototype.toString.call(v) == "[object Array]"; }
function isSpeedFeedSynchronizationActive() { return false; }
function getGlobalPosition(p) { return __vector(p); }
function getFirstTool() { return getNumberOfSections() > 0 ? getSection(0).tool : undefined; }
var EULER_ZXY_R = 5;
var ABC = 3;

// `new StringSubstitution()`: `setValue(name, value)`, then
// `substitute(text)` replaces each `${name}`.
function StringSubstitution() {
  this.values = {};
  this.setValue = function (name, value) { this.values[name] = value; };
  this.substitute = function (text) {
    var result = String(text);
    for (var k in this.values) { result = result.split("${" + k + "}").join(String(this.values[k])); }
    return result;
  };
}
function onUnsupportedCoolant(coolant) {}
function cycleNotSupported() { error(localize("The cycle is not supported.")); }
function onExpandedRapid(x, y, z) { onRapid(x, y, z); }
function onExpandedLinear(x, y, z, feed) { onLinear(x, y, z, feed); }
function onExpandedCircular(clockwise, cx, cy, cz, x, y, z, feed) { onCircular(clockwise, cx, cy, cz, x, y, z, feed); }
function setCurrentDirection(d) {}
function setCurrentPositionX(v) { __position.x = v; }
function setCurrentPositionY(v) { __position.y = v; }
function setCurrentPositionZ(v) { __position.z = v; }
function isWellKnownCommand(command) { return command >= 0 && command <= COMMAND_PROBE_OFF; }
function getQuadrant(angle) { return Math.floor((angle % (2 * Math.PI) + 2 * Math.PI) % (2 * Math.PI) / (Math.PI / 2)); }
// The post's own file, as postc was given it (postc sets it when it reads
// the post; docs/fusion.md, choice 28), and its folder.
var __configurationPath = "";
function getConfigurationPath() { return __configurationPath; }
function getConfigurationFolder() { return __FileSystem_getFolderPath(__configurationPath); }
function loadText(path, encoding) { __unsupported("loadText"); }
function include(path) { __unsupported("include"); }
function execute(path, args, hide, workingFolder) { __unsupported("execute"); }
function isSubSpindleCycle(type) { return false; }
function getMachineConfigurationAsText(machine) { return ""; }
var center = undefined;
var radius = 0;

// `Array.from(items, mapFn)`: a new array of the items of an array,
// `arguments` or a text, each given to `mapFn` (with its index) if there
// is one. Reading the length of undefined or null is the TypeError
// JavaScript's `Array.from` throws for them.
function __Array_from(items, mapFn) {
  var out = [];
  var n = items.length;
  for (var i = 0; i < n; i++) {
    out.push(mapFn === undefined ? items[i] : mapFn(items[i], i));
  }
  return out;
}

// `JSON.stringify(value)`: numbers, texts, booleans, null, arrays and
// objects (functions and undefined properties left out).
function __JSON_stringify(v) {
  if (v === null || v === undefined) { return "null"; }
  if (typeof v == "number") { return (v - v == 0) ? String(v) : "null"; }
  if (typeof v == "boolean") { return String(v); }
  if (typeof v == "string") {
    var out = "\"";
    for (var i = 0; i < v.length; ++i) {
      var c = v.charAt(i);
      var code = v.charCodeAt(i);
      if (c == "\"" || c == "\\") { out += "\\" + c; } else if (c == "\n") { out += "\\n"; } else if (c == "\r") {
        out += "\\r";
      } else if (c == "\t") { out += "\\t"; } else if (code < 32) {
        var hex = code.toString(16);
        while (hex.length < 4) { hex = "0" + hex; }
        out += "\\u" + hex;
      } else { out += c; }
    }
    return out + "\"";
  }
  if (typeof v == "function") { return undefined; }
  var parts = [];
  if (Array.isArray(v)) {
    for (var j = 0; j < v.length; ++j) {
      var item = __JSON_stringify(v[j]);
      parts.push(item === undefined ? "null" : item);
    }
    return "[" + parts.join(",") + "]";
  }
  for (var k in v) {
    if (v[k] === undefined || typeof v[k] == "function") { continue; }
    parts.push(__JSON_stringify(String(k)) + ":" + __JSON_stringify(v[k]));
  }
  return "{" + parts.join(",") + "}";
}
// `JSON.parse(text)`: JSON's values as objects, arrays, texts, numbers,
// booleans and null; an error at the first character that is not JSON.
function __JSON_parse(text) {
  var t = String(text);
  var at = 0;
  function fail() { throw new Error("SyntaxError: JSON.parse: unexpected character at " + at); }
  function blank() { while (at < t.length && " \t\r\n".indexOf(t.charAt(at)) >= 0) { ++at; } }
  function value() {
    blank();
    var c = t.charAt(at);
    if (c == "{") {
      ++at;
      var o = {};
      blank();
      if (t.charAt(at) == "}") { ++at; return o; }
      while (true) {
        blank();
        if (t.charAt(at) != "\"") { fail(); }
        var k = text_();
        blank();
        if (t.charAt(at) != ":") { fail(); }
        ++at;
        o[k] = value();
        blank();
        if (t.charAt(at) == ",") { ++at; continue; }
        if (t.charAt(at) == "}") { ++at; return o; }
        fail();
      }
    }
    if (c == "[") {
      ++at;
      var a = [];
      blank();
      if (t.charAt(at) == "]") { ++at; return a; }
      while (true) {
        a.push(value());
        blank();
        if (t.charAt(at) == ",") { ++at; continue; }
        if (t.charAt(at) == "]") { ++at; return a; }
        fail();
      }
    }
    if (c == "\"") { return text_(); }
    if (t.substring(at, at + 4) == "true") { at += 4; return true; }
    if (t.substring(at, at + 5) == "false") { at += 5; return false; }
    if (t.substring(at, at + 4) == "null") { at += 4; return null; }
    var start = at;
    while (at < t.length && "+-0123456789.eE".indexOf(t.charAt(at)) >= 0) { ++at; }
    if (at == start) { fail(); }
    return Number(t.substring(start, at));
  }
  function text_() {
    ++at;
    var out = "";
    while (at < t.length && t.charAt(at) != "\"") {
      var ch = t.charAt(at);
      if (ch == "\\") {
        ++at;
        var e = t.charAt(at);
        if (e == "n") { out += "\n"; } else if (e == "r") { out += "\r"; } else if (e == "t") { out += "\t"; } else if (e == "b") {
          out += "\b";
        } else if (e == "f") { out += "\f"; } else if (e == "u") {
          out += String.fromCharCode(parseInt(t.substring(at + 1, at + 5), 16));
          at += 4;
        } else { out += e; }
      } else {
        out += ch;
      }
      ++at;
    }
    if (at >= t.length) { fail(); }
    ++at;
    return out;
  }
  var result = value();
  blank();
  if (at < t.length) { fail(); }
  return result;
}

// `new StringBuffer()`: text appended piece by piece.
function StringBuffer() {
  this.text = "";
  this.append = function (t) { this.text += String(t); };
  this.toString = function () { return this.text; };
  this.length = function () { return this.text.length; };
  this.clear = function () { this.text = ""; };
}
// `createModalGroup(specifiers, groups, format)`: codes in groups; a code
// prints when its group's active code changes (or always, with `force`).
function ModalGroup(specifiers, groups, format) {
  this.groups = groups;
  this.formatter = format;
  this.active = [];
  this.force = specifiers !== undefined && specifiers.force === true;
  this.enabled = true;
  this.prefix = "";
  this.suffix = "";
  this.getGroup = function (code) {
    for (var g = 0; g < this.groups.length; ++g) {
      if (this.groups[g].indexOf(code) >= 0) { return g; }
    }
    return -1;
  };
  this.isCodeDefined = function (code) { return this.getGroup(code) >= 0; };
  this.isGroup = function (g) { return g >= 0 && g < this.groups.length; };
  this.getNumberOfGroups = function () { return this.groups.length; };
  this.getActiveCode = function (g) { return this.active[g]; };
  this.hasActiveCode = function (g) { return this.active[g] !== undefined; };
  this.isActiveCode = function (code) { var g = this.getGroup(code); return g >= 0 && this.active[g] == code; };
  this.makeActiveCode = function (code) { var g = this.getGroup(code); if (g >= 0) { this.active[g] = code; } };
  this.inSameGroup = function (a, b) { return this.getGroup(a) == this.getGroup(b); };
  this.reset = function () { this.active = []; };
  this.resetGroup = function (g) { this.active[g] = undefined; };
  this.setForce = function (f) { this.force = f; };
  this.setPrefix = function (p) { this.prefix = p; };
  this.setSuffix = function (p) { this.suffix = p; };
  this.setFormatNumber = function (f) { this.formatter = f; };
  this.isEnabled = function () { return this.enabled; };
  this.enable = function () { this.enabled = true; };
  this.disable = function () { this.enabled = false; };
  this.setStrict = function (v) {};
  this.setAutoReset = function (v) {};
  this.setLogUndefined = function (v) {};
  this.format = function (code) {
    if (!this.enabled) { return ""; }
    var g = this.getGroup(code);
    if (g < 0) { error(subst(localize("Code '%1' is not defined in the modal group."), code)); }
    if (!this.force && this.active[g] == code) { return ""; }
    this.active[g] = code;
    return this.prefix + this.formatter.format(code) + this.suffix;
  };
}
function createModalGroup(specifiers, groups, format) { return new ModalGroup(specifiers, groups, format); }

// ---- The setup's fixture ----
// postc's toolpaths name no fixture: its box is empty, at the origin, as
// `getWorkpiece()` is for a job without material (docs/fusion.md, choice 32).
function getFixture() { return { lower: new Vector(0, 0, 0), upper: new Vector(0, 0, 0) }; }
// ---- What postc does not run yet: an error when the post calls it ----
function __unsupported(name) {
  error("postc does not run `" + name + "` of Fusion's host yet (docs/fusion.md)");
}
// Records: postc's records are the toolpath's events (FeedRate records not
// counted), numbered from 0; of the record after the current one, postc
// knows whether it is a move (docs/fusion.md, choice 22).
var __recordId = 0;
var __nextMotion = 0;
function __at(record, nextMotion) {
  __recordId = record;
  __nextMotion = nextMotion;
}
function Record(id, motion) {
  this.id = id;
  this.motion = motion;
  this.getId = function () { return this.id; };
  this.isValid = function () { return true; };
  this.isMotion = function () { return this.motion; };
}
function getCurrentRecordId() { return __recordId; }
function getNextRecord() { return new Record(__recordId + 1, __nextMotion != 0); }
function getRecord(id) { __unsupported("getRecord"); }
// postc draws no pictures of tools: there is no renderer (null), which the
// posts that draw them test for (`if (toolRenderer)`) (docs/fusion.md,
// choice 26).
function createToolRenderer() { return null; }
function redirectToFile(path) { __unsupported("redirectToFile"); }
function getOutputPath() { return __outputPath; }
function getIntermediatePath() { __unsupported("getIntermediatePath"); }
function findFile(path) { __unsupported("findFile"); }
function setExitCode(code) { __unsupported("setExitCode"); }
function isProbingCycle() { return false; }
function isPolarModeActive() { return false; }
function setWriteInvocations(on) {}
function setWriteStack(on) {}
var POLAR_MODE_OFF = 0;
// The model image a setup sheet shows: none.
var modelImagePath = "";
var COMMAND_DISPLAY_MESSAGE = 44;
// Newer engines than the declarations name it; its value is postc's.
var COMMAND_LIVE_ALIGNMENT = 45;

// ---- Dates: the job's date and time (`--set date=`, `--set time=`) ----
var __date = "";
var __time = "";
// The job's date and time, read when asked (a post may make its `Date`
// before the job is known).
function __dateParts() {
  var months = ["January", "February", "March", "April", "May", "June", "July", "August", "September", "October",
    "November", "December"];
  var words = __date.split(" ");
  var iso = __date.split("-");
  var p = { year: 1970, month: 0, day: 1, hours: 0, minutes: 0, seconds: 0 };
  if (words.length == 4) {
    p.month = Math.max(0, months.indexOf(words[1]));
    p.day = parseInt(words[2], 10);
    p.year = parseInt(words[3], 10);
  } else if (iso.length == 3) {
    p.year = parseInt(iso[0], 10);
    p.month = parseInt(iso[1], 10) - 1;
    p.day = parseInt(iso[2], 10);
  }
  var clock = __time.split(":");
  if (clock.length >= 2) {
    p.hours = parseInt(clock[0], 10);
    p.minutes = parseInt(clock[1], 10);
  }
  if (clock.length >= 3) {
    p.seconds = parseInt(clock[2], 10);
  }
  return p;
}
function Date() {
  var two = function (n) { return n < 10 ? "0" + n : "" + n; };
  this.getFullYear = function () { return __dateParts().year; };
  this.getYear = function () { return __dateParts().year - 1900; };
  this.getMonth = function () { return __dateParts().month; };
  this.getDate = function () { return __dateParts().day; };
  // The day of the week, 0 for Sunday (Sakamoto's method).
  this.getDay = function () {
    var p = __dateParts();
    var y = p.month < 2 ? p.year - 1 : p.year;
    var t = [0, 3, 2, 5, 0, 3, 5, 1, 4, 6, 2, 4];
    return (((y + Math.floor(y / 4) - Math.floor(y / 100) + Math.floor(y / 400) + t[p.month] + p.day) % 7) + 7) % 7;
  };
  this.getHours = function () { return __dateParts().hours; };
  this.getMinutes = function () { return __dateParts().minutes; };
  this.getSeconds = function () { return __dateParts().seconds; };
  this.getMilliseconds = function () { return 0; };
  this.getTime = function () { return 0; };
  this.toLocaleDateString = function () { return __date; };
  this.toLocaleTimeString = function () { return __time; };
  this.toLocaleString = function () { return __date + " " + __time; };
  this.toDateString = function () { return __date; };
  this.toTimeString = function () { return __time; };
  this.toString = function () { return __date + " " + __time; };
  this.toISOString = function () {
    var p = __dateParts();
    return p.year + "-" + two(p.month + 1) + "-" + two(p.day) + "T" + two(p.hours) + ":" + two(p.minutes) + ":" +
      two(p.seconds) + ".000Z";
  };
}

// ---- The program that made the job (Fusion's `generated-by`) ----
// Fusion hands every post the CAM product and its version as the global
// parameter `generated-by`, with the others after `onOpen` ("Inventor HSM
// Ultimate 6.2.0.15626" in Autodesk's debug trace of fanuc.cps): the
// job's product, else postc, what a Vectric post's `[PRODUCT]` prints
// (docs/fusion.md, choice 9). postc's runtime calls this before
// `__fusion_open`.
function __fusion_job(product) {
  if (typeof product == "string") {
    __parameters["generated-by"] = product;
  }
}

// ---- Entry points a post may leave out ----
function onOpen() {}
function onClose() {}
function onTerminate() {}
function onSection() {}
function onSectionEnd() {}
function onParameter(name, value) {}
function onComment(text) {}
function onDwell(seconds) {}
function onSpindleSpeed(speed) {}
function onRadiusCompensation() {}
function onCommand(command) {}
function onRapid(x, y, z) {}
function onLinear(x, y, z, feed) {}
function onCircular(clockwise, cx, cy, cz, x, y, z, feed) { linearize(tolerance); }
function onMovement(m) {}
function onPassThrough(text) {}
function onCycle() {}
// A post without `onCyclePoint` gets its cycles as moves.
function onCyclePoint(x, y, z) { expandCyclePoint(x, y, z); }
function onCycleEnd() {}
function onPower(power) {}
function onUnsupportedCommand(command) {}
function onImpliedCommand(command) {}
function onError(message) {}

// ---- The engine: postc's events as Fusion's calls ----
var __outputPath = "";
function __fusion_open(mm, name, comment, date, time, path, x0, y0, z0, x1, y1, z1, outline, given, record, nextMotion) {
  __at(record, nextMotion);
  if (typeof outline == "string" && outline != "") {
    __outline = __JSON_parse(outline);
    // The first section exists already: it is the outline's first when
    // their tools agree.
    if (__sections.length == 1 && __outline.length > 0 && __outline[0].tool == __sections[0].tool.number) {
      var first = __sections[0];
      var o = __outline[0];
      __future[0] = first;
      first.initialPosition = new Vector(o.x, o.y, o.z);
      first.zRange = new Range(o.zMin, o.zMax);
      first.plannedCycles = o.cycles;
      first.plannedCyclePoints = o.points;
      if (o.cycle >= 0) { first.plannedCycle = __cycleType(o.cycle, o.dwell ? 1 : 0); }
    } else {
      __outline = [];
    }
  }
  __outputPath = __FileSystem_getCombinedPath(path, name + "." + extension);
  __date = date;
  __time = time;
  unit = mm ? MM : IN;
  outputUnit = unit;
  // The program's number is the output file's name when that is a
  // number, as Fusion names the file after it; the comment is the job's
  // notes (docs/fusion.md, choice 9).
  if (/^[0-9]+$/.test(name)) {
    programName = name;
  }
  programComment = comment;
  // The job's material block is Fusion's stock (docs/fusion.md).
  var stock = [x0, y0, z0, x1, y1, z1];
  var known = true;
  for (var i = 0; i < stock.length; ++i) {
    if (typeof stock[i] != "number" || !isFinite(stock[i])) { known = false; }
  }
  if (known) {
    __workpiece = { lower: new Vector(x0, y0, z0), upper: new Vector(x1, y1, z1) };
    var axes = ["x", "y", "z"];
    for (var a = 0; a < 3; ++a) {
      __parameters["stock-lower-" + axes[a]] = stock[a];
      __parameters["stock-upper-" + axes[a]] = stock[a + 3];
    }
  }
  __setProperties(given);
  onOpen();
  for (var p in __parameters) {
    onParameter(p, __parameters[p]);
  }
}

// The post properties the user set (Fusion's post dialog, `post
// --property`), a JSON object of texts by name: each replaces the value
// of the post's property of that name, read as the property's type, before
// `onOpen` (docs/fusion.md, choice 25). A name the post has no property
// for stops the post.
function __setProperties(given) {
  if (typeof given != "string" || given == "") { return; }
  var values = __JSON_parse(given);
  for (var name in values) {
    var p = properties[name];
    if (p === undefined) {
      var known = [];
      for (var k in properties) { known.push(k); }
      __postc_settingError("The post has no property \"" + name + "\" to set; " +
        (known.length > 0 ? "its properties are " + known.join(", ") + "." : "it has no properties."));
    }
    var text = values[name];
    var described = p !== null && typeof p == "object";
    var type = described ? p.type : typeof p;
    var value = text;
    if (type == "boolean") {
      // In any case: Python's `set={"property.x": True}` gives "True".
      var said = text.toLowerCase();
      var yes = said == "true" || said == "yes" || said == "1";
      if (!yes && said != "false" && said != "no" && said != "0") {
        __postc_settingError("The post property \"" + name + "\" is true or false, not \"" + text + "\" (true, yes or 1; false, no or 0).");
      }
      value = yes;
    } else if (type == "enum" && described && p.values instanceof Array && p.values.length > 0) {
      // One of the choices of the post dialog: an entry's `id` (or the
      // entry, when the post lists plain values), as the post lists it.
      var ids = [];
      var found = false;
      for (var c = 0; c < p.values.length; ++c) {
        var entry = p.values[c];
        var id = (entry !== null && typeof entry == "object") ? entry.id : entry;
        ids.push(String(id));
        if (!found && String(id) == text) {
          found = true;
          value = id;
        }
      }
      if (!found) {
        __postc_settingError("The post property \"" + name + "\" is one of " + ids.join(", ") + ", not \"" + text + "\".");
      }
    } else if (type == "number" || type == "integer" || type == "spatial" || type == "angle") {
      value = Number(text);
      if (text.trim() == "" || !isFinite(value)) {
        __postc_settingError("The post property \"" + name + "\" takes a number, not \"" + text + "\".");
      }
    }
    setProperty(name, value);
  }
}

// A toolpath starts: a new section with its tool. The previous section
// ends now, so that its `onSectionEnd` sees the next section.
function __fusion_toolpath(number, diameter, name, toolpathName, jet, speed, notes, coolant, lengthOffset, cutFeed, plungeFeed, safeZ, record, nextMotion, turning, feedPerRev, css, maxRpm, toolpathNotes, ccw) {
  __at(record, nextMotion);
  __toolChanging = false;
  // Under constant surface speed the runtime's speed is the surface
  // speed: the tool's rpm stays the last one given.
  if (css) {
    __surface = speed;
    __maxRpm = maxRpm;
  } else {
    __spindle = jet ? 0 : speed;
  }
  // A toolpath that never moved is no section of Fusion's: the next
  // takes its place (an APT file's INSERT before its first LOAD/TOOL).
  if (__section !== undefined && __section.pending) {
    __sections.pop();
    __section = __sections.length > 0 ? __sections[__sections.length - 1] : undefined;
  }
  var id = __sections.length;
  // The section read ahead, when the toolpath agrees with it.
  var s = id < __outline.length && __outline[id].tool == number ? __outlineSection(id) : undefined;
  if (s === undefined) {
    __outline = [];
    __future = [];
    s = new __Section(id, new Tool(number, diameter, name), toolpathName);
  }
  var t = s.tool;
  t.spindleRPM = __spindle;
  // The spindle's direction: the tool's (a tool is loaded turning
  // clockwise; a SpindleOn that says `ccw` turns it the other way).
  t.clockwise = ccw !== true;
  // The toolpath's tool notes are Fusion's tool comment (docs/fusion.md).
  t.comment = notes;
  t.coolant = coolant;
  if (typeof lengthOffset == "number" && isFinite(lengthOffset)) { t.lengthOffset = lengthOffset; }
  __describeSection(s, name, jet, turning);
  s.feedMode = feedPerRev ? FEED_PER_REVOLUTION : FEED_PER_MINUTE;
  __surfaceSpeed(t, css);
  __operationParameters(s, cutFeed, plungeFeed, safeZ);
  __operationNotes(s, toolpathNotes);
  __sections.push(s);
  __fusion_end_section();
  __section = s;
  __section.pending = true;
}

// A tool's kind from its name (postc's toolpaths give none, or only
// "jet" or "turning"), and the section's type and parameters from its
// tool.
function __describeSection(s, name, jet, turning) {
  var t = s.tool;
  var named = String(name).toLowerCase();
  var kinds = [["ball", TOOL_MILLING_END_BALL], ["bull", TOOL_MILLING_END_BULLNOSE], ["chamfer", TOOL_MILLING_CHAMFER],
    ["v-bit", TOOL_MILLING_CHAMFER], ["face", TOOL_MILLING_FACE], ["spot", TOOL_DRILL_SPOT], ["center drill", TOOL_DRILL_CENTER],
    ["drill", TOOL_DRILL], ["tap", TOOL_TAP_RIGHT_HAND], ["ream", TOOL_REAMER], ["thread", TOOL_MILLING_THREAD]];
  for (var k = 0; k < kinds.length; ++k) {
    if (named.indexOf(kinds[k][0]) >= 0) {
      t.type = kinds[k][1];
      break;
    }
  }
  if (jet) {
    t.jetTool = true;
    t.type = named.indexOf("plasma") >= 0 ? TOOL_PLASMA_CUTTER : (named.indexOf("water") >= 0 ? TOOL_WATER_JET : TOOL_LASER_CUTTER);
    s.type = TYPE_JET;
  }
  // A lathe's tool: its kind by name as well (docs/fusion.md, "Turning").
  if (turning) {
    t.turningTool = true;
    t.type = named.indexOf("groov") >= 0 || named.indexOf("part") >= 0 ? TOOL_TURNING_GROOVING :
      (named.indexOf("thread") >= 0 ? TOOL_TURNING_THREADING : (named.indexOf("boring") >= 0 ? TOOL_TURNING_BORING : TOOL_TURNING_GENERAL));
    t.noseRadius = t.diameter / 2;
    s.type = TYPE_TURNING;
  }
  s.parameters["operation-comment"] = s.name;
  s.parameters["operation:tool_type"] = getToolTypeName(t.type);
  s.parameters["operation:tool_number"] = t.number;
  s.parameters["operation:tool_diameter"] = t.diameter;
  s.parameters["operation:tool_clockwise"] = 1;
}

// The operation's tool feeds and clearance height, as Fusion's engine
// hands an operation's parameters (docs/fusion.md, choice 24): the
// toolpath tool's cut and plunge feeds, and the job's safe Z as the
// absolute clearance height. A value the toolpath does not give is no
// parameter.
function __operationParameters(s, cutFeed, plungeFeed, safeZ) {
  if (typeof cutFeed == "number" && isFinite(cutFeed)) { s.parameters["operation:tool_feedCutting"] = cutFeed; }
  if (typeof plungeFeed == "number" && isFinite(plungeFeed)) { s.parameters["operation:tool_feedPlunge"] = plungeFeed; }
  if (typeof safeZ == "number" && isFinite(safeZ)) {
    s.parameters["operation:clearanceHeight_value"] = safeZ;
    s.parameters["operation:clearanceHeight_absolute"] = 1;
  }
}

// The operation's notes, its parameter `notes` (Fusion hands it before
// the section's `onSection` when the operation has notes, as the debug
// trace of ../shared/fusion-real shows): the toolpath's notes; no
// parameter when it has none.
function __operationNotes(s, notes) {
  if (typeof notes == "string" && notes != "") { s.parameters["notes"] = notes; }
}

// Section `i` of the outline, made once: its tool, where it starts, the
// Z it spans, the cycle it starts with.
function __outlineSection(i) {
  if (__future[i] !== undefined) { return __future[i]; }
  var o = __outline[i];
  var t = new Tool(o.tool, o.diameter, o.name);
  t.spindleRPM = o.jet ? 0 : o.speed;
  t.comment = o.notes;
  t.coolant = o.coolant;
  t.lengthOffset = o.lengthOffset;
  var s = new __Section(i, t, o.toolpath);
  __describeSection(s, o.name, o.jet, o.turning);
  __operationNotes(s, o.toolpathNotes);
  s.initialPosition = new Vector(o.x, o.y, o.z);
  s.zRange = new Range(o.zMin, o.zMax);
  s.plannedCycles = o.cycles;
  s.plannedCyclePoints = o.points;
  if (o.cycle >= 0) {
    s.plannedCycle = __cycleType(o.cycle, o.dwell ? 1 : 0);
    s.startsWithCycle = true;
    s.strategy = "drill";
    s.parameters["operation-strategy"] = "drill";
    s.parameters["operation:cycleType"] = s.plannedCycle;
  }
  __future[i] = s;
  return s;
}

function __fusion_end_section() {
  if (currentSection !== undefined && !currentSection.ended) {
    currentSection.ended = true;
    currentSection.finalPosition = __vector(__position);
    onSectionEnd();
  }
}

// The section's first move: Fusion calls `onSection` with the section's
// initial position known. The moves call it only while the section waits
// for its first move, so that the others cost no call.
function __fusion_begin(x, y, z) {
  var s = __section;
  if (s === undefined || !s.pending) { return; }
  s.pending = false;
  // Fusion refuses an operation the post's capabilities do not include;
  // setup sheets and intermediate posts take every operation.
  var every = (capabilities & (CAPABILITY_SETUP_SHEET | CAPABILITY_INTERMEDIATE)) != 0;
  if (!every && s.type == TYPE_MILLING && (capabilities & CAPABILITY_MILLING) == 0) {
    error(localize("The post does not support milling operations (its capabilities)."));
  }
  if (!every && s.type == TYPE_JET && (capabilities & CAPABILITY_JET) == 0) {
    error(localize("The post does not support jet operations (its capabilities)."));
  }
  if (!every && s.type == TYPE_TURNING && (capabilities & CAPABILITY_TURNING) == 0) {
    error(localize("The post does not support turning operations (its capabilities)."));
  }
  s.initialPosition = new Vector(x, y, z);
  if (s.zRange === undefined) { s.zRange = new Range(z, z); }
  currentSection = s;
  tool = s.tool;
  spindleSpeed = tool.spindleRPM;
  movement = MOVEMENT_RAPID;
  radiusCompensation = RADIUS_COMPENSATION_OFF;
  for (var name in s.parameters) {
    onParameter(name, s.parameters[name]);
  }
  onSection();
  if (__compensation != RADIUS_COMPENSATION_OFF) {
    radiusCompensation = __compensation;
    onRadiusCompensation();
  }
}

// Cutter compensation: Fusion calls `onRadiusCompensation` before the
// move that starts or ends it; one that comes before the section's first
// move waits for `onSection`.
var __compensation = RADIUS_COMPENSATION_OFF;
function __fusion_compensation(side, record, nextMotion) {
  __at(record, nextMotion);
  __compensation = side;
  if (__section !== undefined && __section.pending) { return; }
  if (side != radiusCompensation) {
    radiusCompensation = side;
    onRadiusCompensation();
  }
}

// Coolant is the operation's tool's: a change before the section's first
// move is its tool's coolant; a change within a section is a command.
function __fusion_coolant(coolant, record, nextMotion) {
  __at(record, nextMotion);
  if (__section !== undefined && __section.pending) {
    __section.tool.coolant = coolant;
    return;
  }
  if (currentSection !== undefined) {
    tool.coolant = coolant;
    onCommand(coolant == COOLANT_OFF ? COMMAND_COOLANT_OFF : COMMAND_COOLANT_ON);
  }
}

// Constant surface speed (a lathe's G96): the last surface speed the
// toolpath gave, in metres (feet) a minute, and the highest rpm then.
var __surface = 0;
var __maxRpm = 0;

// The tool's spindle mode: under constant surface speed its
// `surfaceSpeed` is Fusion's, millimetres (inches) a minute, as posts
// divide it by 1000 (12) to print it, and its `maximumSpindleSpeed` the
// toolpath's highest rpm (0 when none is given).
function __surfaceSpeed(t, css) {
  if (css) {
    t.spindleMode = SPINDLE_CONSTANT_SURFACE_SPEED;
    t.surfaceSpeed = __surface * (unit == MM ? 1000 : 12);
    t.maximumSpindleSpeed = typeof __maxRpm == "number" && isFinite(__maxRpm) ? __maxRpm : 0;
  } else {
    t.spindleMode = SPINDLE_CONSTANT_SPINDLE_SPEED;
    t.surfaceSpeed = 0;
    t.maximumSpindleSpeed = 0;
  }
}

// A tool change: its spindle speed belongs to the section that follows.
var __toolChanging = false;
function __fusion_tool_change(record, nextMotion) {
  __at(record, nextMotion);
  __toolChanging = true;
}

function __fusion_spindle(speed, record, nextMotion, css, maxRpm, ccw) {
  __at(record, nextMotion);
  // The direction is the tool's: the section's that waits for its first
  // move, else the current one's (at a tool change, the next toolpath's
  // `__fusion_toolpath` hands it).
  if (!__toolChanging) {
    if (__section !== undefined && __section.pending) {
      __section.tool.clockwise = ccw !== true;
    } else if (currentSection !== undefined) {
      tool.clockwise = ccw !== true;
    }
  }
  // Constant surface speed: the speed is metres (feet) a minute, the
  // tool's rpm stays (docs/fusion.md, "Turning").
  if (css) {
    __surface = speed;
    __maxRpm = maxRpm;
    if (!__toolChanging && __section !== undefined) { __surfaceSpeed(__section.tool, true); }
    return;
  }
  __spindle = speed;
  if (__toolChanging) {
    return;
  }
  if (__section !== undefined && __section.pending) {
    __surfaceSpeed(__section.tool, false);
    __section.tool.spindleRPM = speed;
  } else if (currentSection !== undefined && speed != spindleSpeed) {
    spindleSpeed = speed;
    onSpindleSpeed(speed);
  }
}

function __fusion_moved(x, y, z) {
  // Set in place: the host's position is never handed out (every reader
  // copies it), so no vector is made per move.
  __position.x = x;
  __position.y = y;
  __position.z = z;
  if (currentSection !== undefined) { currentSection.zRange.expandTo(z); }
}

function __fusion_rapid(x, y, z, record, nextMotion) {
  __at(record, nextMotion);
  if (__section !== undefined && __section.pending) { __fusion_begin(x, y, z); }
  movement = MOVEMENT_RAPID;
  onRapid(x, y, z);
  __fusion_moved(x, y, z);
}

function __fusion_linear(x, y, z, feed, plunge, record, nextMotion) {
  __at(record, nextMotion);
  if (__section !== undefined && __section.pending) { __fusion_begin(x, y, z); }
  movement = plunge ? MOVEMENT_PLUNGE : MOVEMENT_CUTTING;
  feedrate = feed;
  onLinear(x, y, z, feed);
  __fusion_moved(x, y, z);
}

// An arc as the post's settings allow it: linearized when its plane is
// not allowed (`allowedCircularPlanes`), when it is helical and
// `allowHelicalMoves` is off, or when its radius or sweep is outside
// `minimumCircularRadius` .. `maximumCircularRadius`,
// `minimumCircularSweep`, `minimumChordLength`; split into equal parts
// when its sweep is over `maximumCircularSweep`; else one `onCircular`.
// An arc; `plunge`: a helix the toolpath marks as plunging, Fusion's
// helical ramp (`MOVEMENT_RAMP_HELIX`).
function __fusion_circular(clockwise, cx, cy, cz, x, y, z, feed, sweep, radius, plane, record, nextMotion, plunge) {
  __at(record, nextMotion);
  if (__section !== undefined && __section.pending) { __fusion_begin(x, y, z); }
  movement = plunge === true ? MOVEMENT_RAMP_HELIX : MOVEMENT_CUTTING;
  feedrate = feed;
  var start = __vector(__position);
  var w = __planeAxes(plane)[2];
  var c = {
    clockwise: clockwise,
    center: new Vector(cx, cy, cz),
    start: start,
    end: new Vector(x, y, z),
    sweep: Math.abs(sweep),
    radius: radius,
    plane: plane,
    feed: feed
  };
  // A helix's centre is at its start along the plane's normal.
  c.center[w] = start[w];
  __circular = c;
  var helical = isHelical();
  var planeAllowed = allowedCircularPlanes === undefined || (allowedCircularPlanes & (1 << plane)) != 0;
  var chord = Math.sqrt((x - start.x) * (x - start.x) + (y - start.y) * (y - start.y) + (z - start.z) * (z - start.z));
  var full = c.sweep > Math.PI && chord < 1e-9;
  if (!planeAllowed || (helical && !allowHelicalMoves) || radius < minimumCircularRadius ||
      radius > maximumCircularRadius || c.sweep < minimumCircularSweep || (!full && chord < minimumChordLength)) {
    linearize(tolerance);
    return;
  }
  var parts = Math.max(1, Math.ceil(c.sweep / maximumCircularSweep - 1e-9));
  if (parts == 1) {
    // The arc in one part is `c` itself: its centre at the start along
    // the normal, from the current position to its end.
    onCircular(clockwise, c.center.x, c.center.y, c.center.z, x, y, z, feed);
    __fusion_moved(x, y, z);
    return;
  }
  for (var i = 1; i <= parts; ++i) {
    var p = i == parts ? c.end : getPositionU(i / parts);
    var center = __vector(c.center);
    center[w] = start[w] + (c.end[w] - start[w]) * (i - 1) / parts;
    __circular = {
      clockwise: clockwise,
      center: center,
      start: __vector(__position),
      end: __vector(p),
      sweep: c.sweep / parts,
      radius: radius,
      plane: plane,
      feed: feed
    };
    onCircular(clockwise, center.x, center.y, center.z, p.x, p.y, p.z, feed);
    __fusion_moved(p.x, p.y, p.z);
    __circular = c;
  }
}

// ---- Drilling cycles ----
// postc's cycle kinds (`DRILL_KIND`) as Fusion's cycle types.
function __cycleType(kind, dwell) {
  switch (kind) {
  case 0: return dwell > 0 ? "counter-boring" : "drilling";
  case 1: return "deep-drilling";
  case 2: return "chip-breaking";
  case 3: return "tapping";
  case 4: return "boring";
  default: return "reaming";
  }
}

// A cycle starts: its holes are read until it ends, then Fusion's calls
// are made with the whole cycle known (`isLastCyclePoint`,
// `getNumberOfCyclePoints`; docs/fusion.md, choice 19).
var __cycleRead = undefined;
var __cyclePoints = [];
var __cyclePointId = -1;
function __fusion_cycle(kind, clearance, retract, stock, bottom, feed, peck, dwell, pitch, record, nextMotion) {
  __at(record, nextMotion);
  var depth = stock - bottom;
  var pecking = typeof peck == "number" && isFinite(peck) && peck > 0;
  var step = pecking ? peck : depth;
  var c = {
    clearance: clearance,
    retract: retract,
    stock: stock,
    depth: depth,
    bottom: bottom,
    feedrate: feed,
    plungeFeedrate: feed,
    retractFeedrate: feed,
    dwell: dwell,
    incrementalDepth: step,
    incrementalDepthReduction: 0,
    minimumIncrementalDepth: step,
    accumulatedDepth: kind == 2 ? depth : step,
    chipBreakDistance: step / 2,
    plungesPerRetract: kind == 2 ? Math.max(1, Math.ceil(depth / step)) : 1,
    shift: 0,
    backBoreDistance: 0,
    stopSpindle: 0,
    compensation: "",
    positionedSpindle: false
  };
  if (typeof pitch == "number" && isFinite(pitch)) { c.pitch = pitch; }
  __cycleRead = { type: __cycleType(kind, dwell), cycle: c, points: [] };
}

function __fusion_cycle_point(x, y, record, nextMotion) {
  __at(record, nextMotion);
  if (__cycleRead !== undefined) { __cycleRead.points.push(new Vector(x, y, __cycleRead.cycle.bottom)); }
}

// The cycle ends: `onSection` first when the cycle starts its section
// (the tool above the first hole at the clearance plane), then
// `onCycle`, `onCyclePoint` for each hole, `onCycleEnd`.
function __fusion_cycle_end(record, nextMotion) {
  __at(record, nextMotion);
  var c = __cycleRead;
  __cycleRead = undefined;
  if (c === undefined || c.points.length == 0) { return; }
  var s = __section;
  if (s !== undefined && s.pending) {
    s.startsWithCycle = true;
    s.strategy = "drill";
    s.parameters["operation-strategy"] = "drill";
    s.parameters["operation:cycleType"] = c.type;
    if (c.cycle.pitch !== undefined) { s.tool.threadPitch = c.cycle.pitch; }
  }
  if (s !== undefined) { s.cycles.push(c); }
  var first = c.points[0];
  if (s !== undefined && s.pending) {
    __fusion_begin(first.x, first.y, c.cycle.clearance);
    __fusion_moved(first.x, first.y, c.cycle.clearance);
  } else if (Math.abs(__position.x - first.x) > 1e-9 || Math.abs(__position.y - first.y) > 1e-9 ||
             Math.abs(__position.z - c.cycle.clearance) > 1e-9) {
    // Within a section, Fusion's linking moves take the tool over the
    // first hole at the clearance plane before the cycle starts.
    if (__position.z < c.cycle.clearance) { __fusion_rapid(__position.x, __position.y, c.cycle.clearance, __recordId, __nextMotion); }
    __fusion_rapid(first.x, first.y, Math.max(__position.z, c.cycle.clearance), __recordId, __nextMotion);
    if (__position.z > c.cycle.clearance) { __fusion_rapid(first.x, first.y, c.cycle.clearance, __recordId, __nextMotion); }
  }
  cycleType = c.type;
  cycle = c.cycle;
  __cyclePoints = c.points;
  movement = MOVEMENT_CUTTING;
  feedrate = cycle.feedrate;
  // Once a post expands a hole, Fusion reads the rest of the cycle as
  // expanded too (`cycleExpanded` stays set until the next cycle).
  cycleExpanded = false;
  onCycle();
  for (var i = 0; i < c.points.length; ++i) {
    var p = c.points[i];
    __cyclePointId = i;
    onCyclePoint(p.x, p.y, p.z);
    // A canned cycle leaves the tool at the clearance plane above the
    // hole (G98); an expanded one where its moves took it.
    if (!cycleExpanded) { __fusion_moved(p.x, p.y, cycle.clearance); }
  }
  onCycleEnd();
  __cyclePointId = -1;
  __cyclePoints = [];
}

function isFirstCyclePoint() { return __cyclePointId == 0; }
function isLastCyclePoint() { return __cyclePointId >= 0 && __cyclePointId == __cyclePoints.length - 1; }
function getCyclePointId() { return __cyclePointId; }
function getNumberOfCyclePoints() { return __cyclePoints.length; }
function getCyclePoint(i) { return __vector(__cyclePoints[i]); }
function isTappingCycle() { return cycleType.indexOf("tapping") >= 0; }

// To X Y at the cycle's clearance plane (posts pass the hole to go over
// it, or the current position to go up only).
function repositionToCycleClearance(c, x, y, z) {
  __expandedRapid(x, y, c.clearance);
}

function __expandedRapid(x, y, z) {
  movement = MOVEMENT_RAPID;
  onExpandedRapid(x, y, z);
  __fusion_moved(x, y, z);
}
function __expandedLinear(x, y, z, feed) {
  movement = MOVEMENT_CUTTING;
  feedrate = feed;
  onExpandedLinear(x, y, z, feed);
  __fusion_moved(x, y, z);
}

// The hole as moves (Fusion's `expandCyclePoint`): up to the clearance
// plane, over the hole, down to the R plane; the feed to the bottom, in
// pecks for deep drilling (back to the R plane after each) and chip
// breaking (back `chipBreakDistance`); the dwell; out at the feed for
// boring, reaming and tapping, else at rapid; up to the clearance plane.
function expandCyclePoint(x, y, z) {
  cycleExpanded = true;
  var c = cycle;
  if (__position.z < c.clearance) { __expandedRapid(__position.x, __position.y, c.clearance); }
  if (Math.abs(__position.x - x) > 1e-9 || Math.abs(__position.y - y) > 1e-9) { __expandedRapid(x, y, __position.z); }
  if (__position.z > c.retract) { __expandedRapid(x, y, c.retract); }
  var pecking = cycleType == "deep-drilling" || cycleType == "chip-breaking";
  var step = pecking && c.incrementalDepth > 0 ? c.incrementalDepth : c.retract - z;
  var at = c.retract;
  while (at - z > 1e-9) {
    at = Math.max(z, at - step);
    __expandedLinear(x, y, at, c.feedrate);
    if (at > z) {
      __expandedRapid(x, y, cycleType == "deep-drilling" ? c.retract : at + c.chipBreakDistance);
      __expandedRapid(x, y, at);
    }
  }
  if (c.dwell > 0) { onDwell(c.dwell); }
  if (cycleType == "boring" || cycleType == "reaming" || isTappingCycle()) {
    __expandedLinear(x, y, c.retract, c.retractFeedrate);
  }
  __expandedRapid(x, y, c.clearance);
}

function __fusion_dwell(seconds, record, nextMotion) {
  __at(record, nextMotion);
  onDwell(seconds);
}
function __fusion_power(on, record, nextMotion) {
  __at(record, nextMotion);
  onPower(on);
}
function __fusion_comment(text, record, nextMotion) {
  __at(record, nextMotion);
  onComment(text);
}

// Text the toolpath inserts as it is (an APT INSERT): each line of it that
// is not empty, ended with `EOL` (the runtime's rule for inserted text).
function __fusion_insert(text, record, nextMotion) {
  __at(record, nextMotion);
  var lines = String(text).split("\n");
  for (var i = 0; i < lines.length; ++i) {
    var line = lines[i];
    if (line.length > 0 && line.charAt(line.length - 1) == "\r") { line = line.substring(0, line.length - 1); }
    if (line != "") { __postc_writeln(line, EOL); }
  }
}

function __fusion_close(record, nextMotion) {
  __at(record, nextMotion);
  __closing = true;
  if (__section !== undefined && __section.pending) {
    __fusion_begin(__position.x, __position.y, __position.z);
  }
  __fusion_end_section();
  onClose();
  onTerminate();
  if (__partial != "") {
    writeln("");
  }
}
