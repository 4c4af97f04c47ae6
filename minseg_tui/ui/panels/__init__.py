"""The panel each kind of step shows above its entries, one per module. A panel shows what
it is given (reactive attributes the lab screen binds to the app's state, or a view the
screen builds from the session in a worker) and posts messages for what the group asks;
the lab screen picks the panel for a step."""
