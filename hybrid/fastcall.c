/* One-state entry point of the decoupling law for CPython: the call path of `law(q, qdot, a, Fc)`.
 *
 * cffi costs about 1 us per call (a buffer conversion per array); this extension reads the
 * NumPy arrays' data pointers directly and calls the generated C, so the law is a few hundred
 * nanoseconds from Python. It is compiled and cached by hybrid/native.py, which puts before
 * this file:
 *
 *   #include "hybrid_<backend>.c"          the generated unit
 *   #define HYBRID_NQ         ...            size of q, qdot, a, Fc, F*, tau
 *   #define HYBRID_ARM_SIZE, HYBRID_SURFACE_SIZE, HYBRID_OPTS_SIZE   the largest parameter arrays
 *   #define HYBRID_LAWS       ...            {"symbol", function, arm size, surface size, opts size}, ...
 *   #define HYBRID_MODULE     ...            the module's name (its cache key)
 *
 * all read off the unit's manifest by hybrid/native.py.
 *
 * Anything off the fast path (lists, other dtypes, N states, a non-OK status) returns None,
 * and the Python caller takes its checked path, which raises the descriptive error. The
 * binding is read-only once made, so concurrent calls from threads are safe.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>
#include <stdlib.h>
#include <string.h>

#define HYBRID_STR_(x) #x
#define HYBRID_STR(x) HYBRID_STR_(x)
#define HYBRID_INIT_(name) PyInit_##name
#define HYBRID_INIT(name) HYBRID_INIT_(name)

typedef int (*law_fn)(const double *, const double *, const double *, const double *, const double *,
                      const double *, const double *, double, double *, double *);

typedef struct {
    const char *symbol;
    law_fn law;
    Py_ssize_t n_arm, n_surface, n_opts;
} law_entry;

static const law_entry LAWS[] = {HYBRID_LAWS};

/* the parameters of one DecouplingLaw, copied at bind time */
typedef struct {
    law_fn law;
    double arm[HYBRID_ARM_SIZE], surface[HYBRID_SURFACE_SIZE], opts[HYBRID_OPTS_SIZE];
    double singular_tol;
} binding;

static const char CAPSULE[] = "hybrid.fastcall.binding";

static void binding_free(PyObject *capsule) { free(PyCapsule_GetPointer(capsule, CAPSULE)); }

static int copy_doubles(PyObject *obj, double *dst, Py_ssize_t n, const char *what) {
    PyArrayObject *arr = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 1, 1, NPY_ARRAY_CARRAY_RO);
    if (arr == NULL) return -1;
    if (PyArray_DIM(arr, 0) != n) {
        PyErr_Format(PyExc_ValueError, "fastcall.bind: %s must hold %zd values, got %zd", what, n,
                     (Py_ssize_t)PyArray_DIM(arr, 0));
        Py_DECREF(arr);
        return -1;
    }
    memcpy(dst, PyArray_DATA(arr), (size_t)n * sizeof(double));
    Py_DECREF(arr);
    return 0;
}

/* bind(symbol, arm, surface, opts, singular_tol) -> capsule; symbol names a law of the unit */
static PyObject *bind(PyObject *self, PyObject *args) {
    const char *symbol;
    PyObject *arm, *surface, *opts;
    double tol;
    size_t i;
    const law_entry *entry = NULL;
    (void)self;
    if (!PyArg_ParseTuple(args, "sOOOd", &symbol, &arm, &surface, &opts, &tol)) return NULL;
    for (i = 0; i < sizeof LAWS / sizeof LAWS[0]; ++i) {
        if (strcmp(LAWS[i].symbol, symbol) == 0) entry = &LAWS[i];
    }
    if (entry == NULL) {
        PyErr_Format(PyExc_ValueError, "fastcall.bind: the unit has no law '%s'", symbol);
        return NULL;
    }
    binding b;
    memset(&b, 0, sizeof b);
    b.law = entry->law;
    b.singular_tol = tol;
    if (copy_doubles(arm, b.arm, entry->n_arm, "arm") || copy_doubles(surface, b.surface, entry->n_surface, "surface")
        || copy_doubles(opts, b.opts, entry->n_opts, "opts"))
        return NULL;
    binding *heap = malloc(sizeof b);
    if (heap == NULL) return PyErr_NoMemory();
    *heap = b;
    PyObject *capsule = PyCapsule_New(heap, CAPSULE, binding_free);
    if (capsule == NULL) free(heap);
    return capsule;
}

/* the data of a 1-D C-contiguous aligned float64 array of HYBRID_NQ values, else NULL */
static const double *pair(PyObject *obj) {
    if (!PyArray_Check(obj)) return NULL;
    PyArrayObject *arr = (PyArrayObject *)obj;
    if (PyArray_NDIM(arr) != 1 || PyArray_DIM(arr, 0) != HYBRID_NQ || PyArray_TYPE(arr) != NPY_DOUBLE
        || !PyArray_ISCARRAY_RO(arr) || PyArray_ISBYTESWAPPED(arr))
        return NULL;
    return (const double *)PyArray_DATA(arr);
}

/* call(binding, which, q, qdot, a, Fc) -> F* (which 0), tau (1), (F*, tau) (2), or None */
static PyObject *call(PyObject *self, PyObject *const *args, Py_ssize_t nargs) {
    (void)self;
    if (nargs != 6) {
        PyErr_SetString(PyExc_TypeError, "fastcall.call takes (binding, which, q, qdot, a, Fc)");
        return NULL;
    }
    const binding *b = PyCapsule_GetPointer(args[0], CAPSULE);
    if (b == NULL) return NULL;
    long which = PyLong_AsLong(args[1]);
    if (which == -1 && PyErr_Occurred()) return NULL;
    const double *q = pair(args[2]), *qd = pair(args[3]), *a = pair(args[4]), *Fc = pair(args[5]);
    if (q == NULL || qd == NULL || a == NULL || Fc == NULL) Py_RETURN_NONE;
    double F[HYBRID_NQ], tau[HYBRID_NQ];
    if (b->law(q, qd, a, Fc, b->arm, b->surface, b->opts, b->singular_tol, F, tau) != 0) Py_RETURN_NONE;
    npy_intp dims[1] = {HYBRID_NQ};
    if (which == 0 || which == 1) {
        PyObject *out = PyArray_SimpleNew(1, dims, NPY_DOUBLE);
        if (out != NULL) memcpy(PyArray_DATA((PyArrayObject *)out), which == 0 ? F : tau, sizeof F);
        return out;
    }
    PyObject *pair_out = PyTuple_New(2);
    if (pair_out == NULL) return NULL;
    for (int k = 0; k < 2; ++k) {
        PyObject *out = PyArray_SimpleNew(1, dims, NPY_DOUBLE);
        if (out == NULL) {
            Py_DECREF(pair_out);
            return NULL;
        }
        memcpy(PyArray_DATA((PyArrayObject *)out), k == 0 ? F : tau, sizeof F);
        PyTuple_SET_ITEM(pair_out, k, out);
    }
    return pair_out;
}

static PyMethodDef methods[] = {
    {"bind", bind, METH_VARARGS, "bind(symbol, arm, surface, opts, singular_tol) -> binding"},
    {"call", (PyCFunction)(void (*)(void))call, METH_FASTCALL,
     "call(binding, which, q, qdot, a, Fc) -> F* (which=0), tau (1), (F*, tau) (2), or None off the fast path"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, HYBRID_STR(HYBRID_MODULE),
                                    "one-state decoupling law for CPython", -1, methods,
                                    NULL, NULL, NULL, NULL};

PyMODINIT_FUNC HYBRID_INIT(HYBRID_MODULE)(void) {
    import_array();
    return PyModule_Create(&module);
}
